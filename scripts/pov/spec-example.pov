// The spec's example scene (scenes/bench/spec-example.yaml) for POV-Ray 3.7, to time against Glint on the same
// picture: 800x600, one ray a pixel, 5 levels of rays, a point light with inverse-square falloff.
// Used by scripts/povray-twin.sh; not part of the product.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 ambient_light rgb 1 }
background { rgb <0.02, 0.02, 0.04> }
camera { perspective location <0, 1.6, -6> look_at <0, 0.9, 0> right x * 800 / 600 angle 60 }
light_source { <-5, 8, -6> color rgb 100 fade_distance 1 fade_power 2 }
#declare Ambient = 0.02;
// matte red: Lambert only
sphere { <-2.2, 1, 0>, 1
  texture { pigment { rgb <0.8, 0.1, 0.1> } finish { ambient Ambient diffuse 1 / pi specular 0 } } }
// clear glass: Fresnel reflection and refraction
sphere { <0, 1, 0>, 1
  texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } }
  interior { ior 1.5 } }
// gold metal: a tinted mirror with a small highlight
sphere { <2.2, 1, 0>, 1
  texture { pigment { rgb <1.0, 0.77, 0.34> } finish { ambient 0 diffuse 0 reflection { rgb <1.0, 0.77, 0.34> metallic } specular 0.5 roughness 0.005 metallic } } }
plane { y, 0
  texture { pigment { rgb 0.5 } finish { ambient Ambient diffuse 1 / pi specular 0 } } }
