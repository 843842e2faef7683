// demo.pov: the README's demo scene.
// Shows: a checkered floor, a mirror sphere, a glass sphere, matte and
// glossy spheres placed by a #while loop, a rectangular area light and a
// point fill light, and lancer's render_settings extension.
// Suits: whitted (default here, fast), shadow, gather, path (reference).
#version 3.7;
#include "colors.inc"

global_settings { assumed_gamma 1.0 max_trace_level 8 }

render_settings {
    integrator "whitted" { }
    width 640
    height 480
    samples 16
}

camera {
    location <0, 2.2, -7.5>
    look_at <0, 0.8, 0>
    right x * image_width / image_height
    angle 50
}

background { color rgb <0.55, 0.65, 0.85> }

// Key light: a physical 2 x 2 panel above and in front of the spheres.
light_source {
    <-2, 7, -3>
    color rgb 45
    area_rectangle <2, 0, 0>, <0, 0, 2>
}
// Fill light: a POV point light, the same at every distance.
light_source { <6, 4, -6> color rgb <0.07, 0.07, 0.08> }

plane {
    y, 0
    texture {
        pigment { checker color rgb 0.8, color rgb 0.15 scale 1 }
        finish { diffuse 0.8 ambient 0.02 }
    }
}

#declare Mirror = texture {
    pigment { color rgb 0.9 }
    finish { diffuse 0 ambient 0 reflection { 0.9 } }
}

sphere { <-1.6, 1, 0.5>, 1 texture { Mirror } }

sphere {
    <0.9, 0.9, -0.6>, 0.9
    texture {
        pigment { color rgbf <0.98, 1, 0.98, 0.95> }
        finish { diffuse 0 ambient 0 specular 0.3 roughness 0.01 reflection { 0.04, 1 fresnel on } }
    }
    interior { ior 1.5 }
}

// A ring of small glossy spheres, coloured around the hue circle.
#declare Count = 9;
#declare I = 0;
#while (I < Count)
    #declare Angle = 2 * pi * I / Count;
    sphere {
        <3.2 * cos(Angle), 0.35, 2.2 + 3.2 * sin(Angle)>, 0.35
        texture {
            pigment { color rgb <0.5 + 0.45 * cos(Angle), 0.5 + 0.45 * cos(Angle - 2.09), 0.5 + 0.45 * cos(Angle + 2.09)> }
            finish { diffuse 0.8 ambient 0.02 phong 0.3 phong_size 60 }
        }
    }
    #declare I = I + 1;
#end

// A box on a tilted plinth, to show transforms.
box {
    <-0.5, 0, -0.5>, <0.5, 1.2, 0.5>
    rotate y * 30
    translate <2.4, 0, 1.6>
    texture { pigment { color rgb <0.8, 0.35, 0.2> } finish { diffuse 0.85 ambient 0.02 } }
}
