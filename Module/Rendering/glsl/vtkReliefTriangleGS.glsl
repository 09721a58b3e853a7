//VTK::System::Dec
// vtkRelief: a geometry shader template that passes triangles through unchanged, for
// vtkOpenGLQuadricReliefMapper where VTK has none (no edges drawn, no wide lines): the
// quadric frame's hull needs each triangle's three corners (vtkReliefQuadricFrame.glsl,
// RELIEF_GEOMETRY_STAGE). The tags are those VTK 9.1 fills in its own geometry shaders
// (vtkOpenGLPolyDataMapper::ReplaceShader*), so VTK's varyings reach the fragments as
// with its edges template; vtkOpenGLShaderCache renames the fragment inputs to GSOutput.

//VTK::PositionVC::Dec
//VTK::PrimID::Dec
//VTK::Color::Dec
//VTK::Normal::Dec
//VTK::Light::Dec
//VTK::TCoord::Dec
//VTK::Picking::Dec
//VTK::DepthPeeling::Dec
//VTK::Clip::Dec
//VTK::Output::Dec

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

void main()
{
  //VTK::Normal::Start
  for (int i = 0; i < 3; i++)
  {
    //VTK::PrimID::Impl
    //VTK::Clip::Impl
    //VTK::Color::Impl
    //VTK::Normal::Impl
    //VTK::Light::Impl
    //VTK::TCoord::Impl
    //VTK::DepthPeeling::Impl
    //VTK::Picking::Impl
    //VTK::PositionVC::Impl
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
  }
  EndPrimitive();
}
