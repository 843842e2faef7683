// function { spline { } } (after POV-Ray's language/splinefunction.pov):
// a spline called in the scene language (the spheres along it) and inside
// a pigment's function (the grey ramp), for each spline kind.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> right x * 1.4 * 4 / 3 up y * 1.4 }
#declare Points = spline {
  -0.25, <0, 0.2, 0> 0, <0, 0, 0> 0.25, <0.25, 0.5, 0> 0.5, <0.5, 0.1, 0> 0.75, <0.75, 0.9, 0> 1, <1, 0.3, 0> 1.25, <1, 0, 0> }
#macro Show(S, Row)
  box { <0, 0, 0.05>, <1, 1, 0.1>
    pigment { function { S(x).y } color_map { [0 rgb <0.1, 0.1, 0.3>] [1 rgb <0.9, 0.8, 0.5>] } }
    finish { ambient 1 diffuse 0 } scale <1, 0.25, 1> translate y * Row }
  #local I = 0;
  #while (I <= 40)
    sphere { S(I / 40) * <1, 0.25, 0>, 0.008 translate y * Row pigment { rgb <1, 0.2, 0.1> } finish { ambient 1 diffuse 0 } }
    #local I = I + 1;
  #end
#end
Show(function { spline { Points linear_spline } }, 0)
Show(function { spline { Points quadratic_spline } }, 0.25)
Show(function { spline { Points cubic_spline } }, 0.5)
Show(function { spline { Points natural_spline } }, 0.75)
