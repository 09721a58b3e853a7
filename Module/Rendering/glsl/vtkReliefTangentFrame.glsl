// vtkRelief: the tangent frame (Policarpo, Oliveira and Comba 2005, s3), for
// vtkOpenGLReliefMapper: the interpolated tangent basis (vtkReliefTangentBasis.glsl)
// over a flat reference surface. The frame interface is described in
// vtkReliefCommon.glsl; written in the GLSL subset GLM also compiles.

#if defined(RELIEF_VERTEX_STAGE)
void reliefFrameVertex()
{
  reliefTangentBasisVertex();
}
#elif defined(RELIEF_GEOMETRY_STAGE)
#define reliefFrameGeometry(vertex) reliefTangentBasisGeometry(vertex)
#else
struct ReliefFrame
{
  vec3 axisU;
  vec3 axisV;
  vec3 normal;
  bool usable;
};

ReliefFrame reliefTangentFrame(ReliefTangentBasis basis)
{
  ReliefFrame frame;
  frame.axisU = basis.tangent / basis.textureScale.x;
  frame.axisV = basis.bitangent / basis.textureScale.y;
  frame.normal = basis.normal;
  frame.usable = true;
  return frame;
}

bool reliefFrameHides(ReliefFrame frame, ReliefFragment fragment)
{
  return false;
}

ReliefRay reliefFrameViewRay(ReliefFrame frame, ReliefFragment fragment)
{
  return reliefViewRay(fragment.tcoord, reliefFlatDirection(fragment.viewVC, frame.axisU,
    frame.axisV, frame.normal, fragment.depthScale));
}

bool reliefFrameRayLeft(ReliefFrame frame, ReliefRay ray, ReliefHit hit)
{
  return false;
}

float reliefFrameHitDistance(ReliefFrame frame, ReliefFragment fragment, ReliefRay ray,
  ReliefHit hit)
{
  return reliefFlatHitDistance(fragment.viewVC, frame.normal, fragment.depthScale, hit);
}

vec3 reliefFrameSurfaceSlope(ReliefFrame frame, ReliefFragment fragment, float distance)
{
  return vec3(0.0f, 0.0f, 0.0f);
}

#if defined(RELIEF_FRAGMENT_STAGE)
ReliefFrame reliefFrameOf(ReliefFragment fragment)
{
  return reliefTangentFrame(reliefTangentBasisOf(fragment));
}
#endif
#endif
