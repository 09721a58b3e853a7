// vtkRelief varyings passed through VTK's geometry shader (edges, wide lines): those
// every frame has; the frame's own follow (its file's RELIEF_GEOMETRY_STAGE section).
in vec3 reliefPositionVSOutput[];
in vec2 reliefTCoordVSOutput[];
out vec3 reliefPositionGSOutput;
out vec2 reliefTCoordGSOutput;
