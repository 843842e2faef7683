// glass.pov: refraction and total internal reflection. A glass sphere and a
// glass slab over a checker floor; the slab is seen edge-on near the grazing
// angle, where light inside it reflects totally.
// Shows: interior { ior }, rgbf/rgbt transparency, Fresnel reflection.
// Suits: whitted (with -p fresnel=true), path (reference).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }

render_settings { integrator "whitted" { fresnel true } width 320 height 240 }

camera { location <0, 2.5, -6> look_at <0, 0.7, 0> right x * 4 / 3 angle 50 }

background { color rgb <0.4, 0.5, 0.7> }
light_source { <-4, 8, -6> color rgb 0.8 }

plane { y, 0 texture { pigment { checker color rgb <0.9, 0.85, 0.7>, color rgb <0.2, 0.25, 0.4> scale 0.6 } finish { ambient 0.05 } } }

#declare Glass = texture {
    pigment { color rgbf <1, 1, 1, 1> }
    finish { ambient 0 diffuse 0 specular 0.4 roughness 0.005 reflection { 0, 1 fresnel on } }
}

sphere { <-1.1, 1, 0>, 1 texture { Glass } interior { ior 1.5 } }

// A thick slab of denser glass, tilted so its far face is seen at grazing
// incidence from inside.
box {
    <-0.8, 0, -0.15>, <0.8, 1.4, 0.15>
    rotate y * 65
    translate <1.4, 0, 0.3>
    texture { pigment { color rgbt <0.8, 1, 0.9, 0.9> } finish { ambient 0 diffuse 0 reflection { 0.02, 1 fresnel on } } }
    interior { ior 1.9 }
}
