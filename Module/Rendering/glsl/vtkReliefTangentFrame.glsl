// vtkRelief: the tangent frame (Policarpo, Oliveira and Comba 2005, s3), for
// vtkOpenGLReliefMapper: the interpolated tangent basis (vtkReliefTangentBasis.glsl)
// over a flat reference surface, a flat frame (vtkReliefFlatFrame.glsl, before this
// file). The frame interface is described in vtkReliefCommon.glsl; written in the GLSL
// subset GLM also compiles.

#if defined(RELIEF_VERTEX_STAGE)
void reliefFrameVertex()
{
  reliefTangentBasisVertex();
}
#elif defined(RELIEF_GEOMETRY_STAGE)
#define reliefFrameGeometry(vertex) reliefTangentBasisGeometry(vertex)
#else
ReliefFrame reliefTangentFrame(ReliefTangentBasis basis)
{
  ReliefFrame frame;
  frame.axisU = basis.tangent / basis.textureScale.x;
  frame.axisV = basis.bitangent / basis.textureScale.y;
  frame.normal = basis.normal;
  frame.usable = true;
  return frame;
}

#if defined(RELIEF_FRAGMENT_STAGE)
ReliefFrame reliefFrameOf(ReliefFragment fragment)
{
  return reliefTangentFrame(reliefTangentBasisOf(fragment));
}
#endif
#endif
