// vtkRelief: what the flat frames (the tangent frame, the derivative frame) share: the
// frame interface of vtkReliefCommon.glsl over a flat reference surface, where the view
// ray is straight in relief texture space and the surface does not tilt along it. A flat
// frame's file builds this ReliefFrame and defines reliefFrameOf(); written in the GLSL
// subset GLM also compiles.

#if !defined(RELIEF_VERTEX_STAGE) && !defined(RELIEF_GEOMETRY_STAGE)
struct ReliefFrame
{
  vec3 axisU;
  vec3 axisV;
  vec3 normal;
  bool usable;
};

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
#endif
