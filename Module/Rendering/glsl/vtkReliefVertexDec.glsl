// vtkRelief vertex inputs and outputs every frame has; the frame's own follow
// (its file's RELIEF_VERTEX_STAGE section).
//VTK::Relief::CameraDec
in vec2 reliefTCoordMC;
out vec3 reliefPositionVSOutput;
out vec2 reliefTCoordVSOutput;
