mesh2 {
        vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
        normal_vectors { 1, <0,0,-1> }
        uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> }
        texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0.5 } } }
        face_indices { 2, <0,1,2>, 1, <0,2,3>3333333333333, 0 }
        normal_indices { 2, <0,0,0>, <0,0,0> }
        uv_indices { 2, <0,1,2>, <0,2,3> }
    }