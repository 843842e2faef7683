// bounded_by can cut, by POV-Ray's two rules. An object's box becomes its
// bound's box where that is smaller, and a ray that misses the box misses
// the object: the ball on the right, bounded by a small sphere behind it,
// keeps only what the rays through that sphere's box see. And a ray must
// meet every bound or start inside it (Ray_In_Bound), a rule POV keeps only
// for objects costly to intersect (polynomials, text, quadrics, CSG): the
// hyperbolic torus of objects/quartic/hyptorus.pov, left, is cut by its
// bounding sphere, smaller than itself. The torus at the top right keeps
// its own, smaller box, and its bound is dropped: it is whole.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -30> look_at <0, 0, 0> angle 60 }
light_source { <-20, 30, -40> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
quartic {
  < 1.0,  0.0,  0.0,   0.0,    2.0,  0.0,  0.0, -2.0,  0.0, -104.0
    0.0,  0.0,  0.0,   0.0,    0.0,  0.0,  0.0,  0.0,  0.0,   0.0
    1.0,  0.0,  0.0,  -2.0,    0.0, 56.0,  0.0,  0.0,  0.0,   0.0
    1.0,  0.0, 104.0,  0.0,  784.0 >
  pigment { rgb <0.8, 0, 0.05> * 0.5 }
  finish { specular 1 roughness 0.005 ambient 0.2 diffuse 0.8 }
  bounded_by { sphere { 0, 14 } }
  rotate <90, 30, 0> rotate <10, 0, 0>
  scale 0.6
  translate <-7, 0, 0>
}
torus { 4, 1.2
  pigment { rgb <0.9, 0.7, 0.2> }
  bounded_by { box { <-6, -2, -6>, <6, 2, 0.5> } }
  rotate -60 * x
  translate <9, 4, 0>
}
sphere { <9, -6, 0>, 3
  pigment { rgb <0.3, 0.8, 0.4> }
  bounded_by { sphere { <9, -6, 6>, 2.5 } }
}
