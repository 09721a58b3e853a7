// vtkRelief frame varyings passed through VTK's geometry shader (edges, wide lines).
in vec3 reliefPositionVSOutput[];
in vec2 reliefTCoordVSOutput[];
out vec3 reliefPositionGSOutput;
out vec2 reliefTCoordGSOutput;
#ifdef RELIEF_VERTEX_NORMALS
in vec3 reliefNormalVSOutput[];
out vec3 reliefNormalGSOutput;
#endif
#ifdef RELIEF_TANGENT_FRAME
in vec3 reliefTangentVSOutput[];
in vec2 reliefTextureScaleVSOutput[];
out vec3 reliefTangentGSOutput;
out vec2 reliefTextureScaleGSOutput;
#endif
#ifdef RELIEF_QUADRIC
in vec2 reliefQuadricVSOutput[];
out vec2 reliefQuadricGSOutput;
#endif
