// Three orthogonal sections of one solid texture of POV-Ray 3.7 (Debian package povray): the
// material's point (X, Y, Z) has the colour of the texture at (X, Y, Z); the section of plane
// Plane (0: xy, x across, y down; 1: xz, x across, z down; 2: yz, y across, z down) passes through
// the middle of the unit block [0, 1]^3; the texture is taken at (X, Y, Z) + Offset. Rendered by render.sh.
#version 3.7;
#include "woodmaps.inc"

#declare Offset = <0.5, -0.5, 0>;  // the rings' axis beside the block: xy end grain, xz quarter-sawn, yz flat-sawn
#declare T_Wood = texture {
  pigment {
    average
    pigment_map {
      [3 wood turbulence 0.06 octaves 4 scale <0.05, 0.05, 1> color_map { M_Wood1A }]
      [1 granite color_map { [0 rgb <0.30, 0.18, 0.10>] [1 rgb <1.00, 0.75, 0.55>] } scale <0.02, 0.02, 0.4>]
    }
  }
}
#declare T_Bedded = texture {
  pigment {
    average
    pigment_map {
      [3 marble turbulence 0.35 octaves 5 lambda 2.2
         color_map { [0.00 rgb <0.86, 0.74, 0.55>] [0.35 rgb <0.78, 0.60, 0.40>]
                     [0.55 rgb <0.55, 0.40, 0.28>] [0.75 rgb <0.70, 0.55, 0.38>]
                     [1.00 rgb <0.86, 0.74, 0.55>] }
         scale 0.16 rotate y * 90]
      [1 granite color_map { [0 rgb 0.35] [1 rgb 1.10] } scale 0.6]
    }
  }
}
#declare Material = texture { #if (Texture = 0) T_Wood #else T_Bedded #end finish { ambient 1 diffuse 0 } }

// Image pixel (u, v) lies at (u, -v, 0) in the scene; Section maps it into the material.
#switch (Plane)
  #case (0) #declare Section = transform { matrix <1, 0, 0,  0, -1, 0,  0, 0, 1,  0, 0, 0.5> } #break
  #case (1) #declare Section = transform { matrix <1, 0, 0,  0, 0, -1,  0, 1, 0,  0, 0.5, 0> } #break
  #case (2) #declare Section = transform { matrix <0, 1, 0,  0, 0, -1,  1, 0, 0,  0.5, 0, 0> } #break
#end

camera { orthographic location <0.5, -0.5, -1> look_at <0.5, -0.5, 0> right x up y }
plane {
  z, 0
  texture { Material translate -Offset transform { Section inverse } }
}
