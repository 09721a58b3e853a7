// vtkRelief frame varyings passed through VTK's geometry shader (edges, wide lines).
in vec3 reliefPositionVSOutput[];
in vec3 reliefNormalVSOutput[];
in vec3 reliefTangentVSOutput[];
in vec2 reliefTCoordVSOutput[];
in vec2 reliefTextureScaleVSOutput[];
out vec3 reliefPositionGSOutput;
out vec3 reliefNormalGSOutput;
out vec3 reliefTangentGSOutput;
out vec2 reliefTCoordGSOutput;
out vec2 reliefTextureScaleGSOutput;
#ifdef RELIEF_QUADRIC
in vec2 reliefQuadricVSOutput[];
out vec2 reliefQuadricGSOutput;
#endif
