// vtkRelief vertex inputs and outputs of the tangent frame (seed 000 s3.4).
//VTK::Relief::CameraDec
in vec3 reliefNormalMC;
in vec3 reliefTangentMC;
in vec2 reliefTCoordMC;
in vec2 reliefTextureScaleMC; // model length of one texture unit along tangent, bitangent
uniform mat3 reliefDirectionMatrix; // model to view for directions, without VBO shift/scale
uniform mat3 reliefNormalMatrix;    // its inverse transpose
out vec3 reliefPositionVSOutput;
out vec3 reliefNormalVSOutput;
out vec3 reliefTangentVSOutput;
out vec2 reliefTCoordVSOutput;
out vec2 reliefTextureScaleVSOutput;
#ifdef RELIEF_QUADRIC
in vec2 reliefQuadricMC; // (a, b) of vtkLocalQuadricFilter, model units
out vec2 reliefQuadricVSOutput;
#endif
