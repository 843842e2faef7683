// procedural.pov: a spiral staircase of boxes and a pyramid of spheres built
// with #macro, #while, #for, #if, #switch and #local.
// Shows: the directive language; expressions and built-in functions.
// Suits: raycast, shadow, whitted, path.
#version 3.7;
#include "colors.inc"
global_settings { assumed_gamma 1.0 }

render_settings { integrator "shadow" { } width 320 height 240 }

camera { location <0, 7, -13> look_at <0, 2.5, 0> right x * 4 / 3 angle 50 }
light_source { <5, 14, -8> color rgb 1.05 }
light_source { <-8, 6, -10> color rgb 0.2 }
plane { y, 0 texture { pigment { color rgb 0.55 } } }

// A box step at height H turned by Angle degrees about the y axis.
#macro Step(H, Angle, Tint)
    box {
        <0.4, -0.06, -0.3>, <2.0, 0.06, 0.3>
        rotate y * Angle
        translate <0, H, 0>
        texture { pigment { color Tint } finish { phong 0.3 } }
    }
#end

#declare Steps = 24;
#for (I, 0, Steps - 1)
    #local Fraction = I / (Steps - 1);
    Step(0.2 + 0.2 * I, I * 25, rgb <Fraction, 0.3, 1 - Fraction>)
#end
// The central column, as a stack of spheres.
#declare K = 0;
#while (K < 10)
    sphere { <0, 0.25 + 0.5 * K, 0>, 0.3 texture { pigment { color White * 0.8 } } }
    #declare K = K + 1;
#end

// A pyramid of spheres: layer L is (N-L) x (N-L); colour by layer parity.
#macro Pyramid(N, Radius, Origin)
    #local L = 0;
    #while (L < N)
        #local Side = N - L;
        #local A = 0;
        #while (A < Side)
            #local B = 0;
            #while (B < Side)
                #switch (mod(L, 3))
                    #case (0) #local Tint = Red; #break
                    #case (1) #local Tint = Yellow; #break
                    #else #local Tint = Orange;
                #end
                sphere {
                    Origin + <(A - (Side - 1) / 2) * 2 * Radius, Radius * (1 + L * sqrt(2)), (B - (Side - 1) / 2) * 2 * Radius>,
                    Radius
                    texture { pigment { color Tint } finish { specular 0.3 } }
                }
                #local B = B + 1;
            #end
            #local A = A + 1;
        #end
        #local L = L + 1;
    #end
#end

Pyramid(5, 0.25, <4.2, 0, 1>)
#if (Steps > 20)
    Pyramid(3, 0.3, <-4.2, 0, 1>)
#else
    #error "the staircase is too short"
#end
