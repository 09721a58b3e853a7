// vtkRelief vertex inputs and outputs of the frame: the tangent frame (seed 000 s3.4),
// or only the vertex normal, if any, for the derivative frame (seed 003).
//VTK::Relief::CameraDec
in vec2 reliefTCoordMC;
out vec3 reliefPositionVSOutput;
out vec2 reliefTCoordVSOutput;
#ifdef RELIEF_VERTEX_NORMALS
in vec3 reliefNormalMC;
uniform mat3 reliefNormalMatrix; // model to view for normals, without VBO shift/scale
out vec3 reliefNormalVSOutput;
#endif
#ifdef RELIEF_TANGENT_FRAME
in vec3 reliefTangentMC;
in vec2 reliefTextureScaleMC; // model length of one texture unit along tangent, bitangent
uniform mat3 reliefDirectionMatrix; // model to view for directions, without VBO shift/scale
out vec3 reliefTangentVSOutput;
out vec2 reliefTextureScaleVSOutput;
#endif
#ifdef RELIEF_QUADRIC
in vec2 reliefQuadricMC; // (a, b) of vtkLocalQuadricFilter, model units
out vec2 reliefQuadricVSOutput;
#endif
