// vtkRelief: the derivative frame (Tichenor 2012, "Texture coordinate offset
// calculations"), for vtkOpenGLDerivativeReliefMapper: a fragment's texture-space axes
// from screen-space derivatives, for meshes without tangents; with RELIEF_VERTEX_NORMALS,
// depth along the interpolated vertex normal; a flat frame (vtkReliefFlatFrame.glsl,
// before this file). The frame interface is described in vtkReliefCommon.glsl; written in the GLSL
// subset GLM also compiles: the unit tests check the axes on the CPU against triangles' exact
// texture mappings.

#if defined(RELIEF_VERTEX_STAGE)
#ifdef RELIEF_VERTEX_NORMALS
in vec3 reliefNormalMC;
uniform mat3 reliefNormalMatrix; // model to view for normals, without VBO shift/scale
out vec3 reliefNormalVSOutput;
#endif

void reliefFrameVertex()
{
#ifdef RELIEF_VERTEX_NORMALS
  reliefNormalVSOutput = reliefNormalMatrix * reliefNormalMC;
#endif
}
#elif defined(RELIEF_GEOMETRY_STAGE)
#ifdef RELIEF_VERTEX_NORMALS
in vec3 reliefNormalVSOutput[];
out vec3 reliefNormalGSOutput;
#define reliefFrameGeometry(vertex) reliefNormalGSOutput = reliefNormalVSOutput[vertex]
#else
#define reliefFrameGeometry(vertex)
#endif
#else

struct ReliefAxes
{
  vec3 u;      // gradient of u in view space: a displacement d moves u by dot(u, d)
  vec3 v;      // gradient of v
  bool usable; // false where the derivatives hold no mapping (no texture or surface area)
};

// alongX, alongY: change of the view-space position from one pixel to the next along
// screen x and y; uvAlongX, uvAlongY: change of the texture coordinates; normal: the
// direction relief depth is measured along, the face's or the interpolated vertex normal.
// The axes are the dual basis of (alongX, alongY, normal): dot(u, alongX) = uvAlongX.x,
// dot(u, alongY) = uvAlongY.x and dot(u, normal) = 0, and alike for v. Along the face
// this is the triangle's own affine texture mapping, exact for any skew of its texture
// coordinates; Tichenor (2012) projects on normalized dFdx and dFdy instead, which holds only
// where they are perpendicular. A displacement along the normal leaves (u, v) unchanged:
// with interpolated normals the texture axes turn with them, continuous across an edge
// where its two faces share their vertex normals.
ReliefAxes reliefDerivativeAxes(vec3 alongX, vec3 alongY, vec2 uvAlongX, vec2 uvAlongY, vec3 normal)
{
  vec3 acrossY = cross(alongY, normal); // dot(acrossY, alongY) = 0
  vec3 acrossX = cross(normal, alongX); // dot(acrossX, alongX) = 0
  float volume = dot(alongX, acrossY);  // = dot(acrossX, alongY) = det(alongX, alongY, normal)
  float uvArea = uvAlongX.x * uvAlongY.y - uvAlongX.y * uvAlongY.x;
  // both determinants against the lengths they are made of: the sines of the angles
  // the frame spans, free of the mesh's units and the texture's tiling
  float extent = length(alongX) * length(alongY) * length(normal);
  float uvExtent = length(uvAlongX) * length(uvAlongY);
  ReliefAxes axes;
  axes.usable = abs(volume) > 1e-4f * extent && abs(uvArea) > 1e-4f * uvExtent &&
    uvExtent > 0.0f && !isnan(volume) && !isinf(volume) && !isnan(uvArea) && !isinf(uvArea);
  // no mapping: no tilt either, and nothing not finite passes on
  axes.u = vec3(0.0f, 0.0f, 0.0f);
  axes.v = vec3(0.0f, 0.0f, 0.0f);
  if (axes.usable)
  {
    axes.u = (acrossY * uvAlongX.x + acrossX * uvAlongY.x) / volume;
    axes.v = (acrossY * uvAlongX.y + acrossX * uvAlongY.y) / volume;
  }
  return axes;
}

// The direction of `vector`, or `fallback` where it has none (zero, or not finite).
vec3 reliefUnitOr(vec3 vector, vec3 fallback)
{
  float size = length(vector);
  return size > 0.0f && !isinf(size) && !isnan(size) ? vector / size : fallback;
}

// The triangle's own mapping, from how position and texture coordinates change from
// pixel to pixel; its normal faces the viewer. vertexNormal: the interpolated vertex
// normal (read with RELIEF_VERTEX_NORMALS only).
ReliefFrame reliefDerivativeFrame(ReliefFragment fragment, vec3 vertexNormal)
{
  vec3 faceNormal = cross(fragment.positionAlongX, fragment.positionAlongY);
  faceNormal = dot(faceNormal, fragment.viewVC) > 0.0f ? -faceNormal : faceNormal;
  ReliefFrame frame;
  frame.normal = reliefUnitOr(faceNormal, -fragment.viewVC);
#ifdef RELIEF_VERTEX_NORMALS
  // smooth: depth along the interpolated normal, turned to the face's visible side;
  // near an outline it may still face away from the viewer, and no ray can go in along
  // it: the face's normal then
  vec3 smoothNormal = reliefUnitOr(vertexNormal, frame.normal);
  smoothNormal = dot(smoothNormal, faceNormal) < 0.0f ? -smoothNormal : smoothNormal;
  frame.normal = dot(smoothNormal, fragment.viewVC) < -1e-3f ? smoothNormal : frame.normal;
#endif
  ReliefAxes axes = reliefDerivativeAxes(fragment.positionAlongX, fragment.positionAlongY,
    fragment.tcoordAlongX, fragment.tcoordAlongY, frame.normal);
  frame.axisU = axes.u;
  frame.axisV = axes.v;
  frame.usable = axes.usable;
  return frame;
}

#if defined(RELIEF_FRAGMENT_STAGE)
#ifdef RELIEF_VERTEX_NORMALS
in vec3 reliefNormalVSOutput;
#define RELIEF_INTERPOLATED_NORMAL reliefNormalVSOutput
#else
#define RELIEF_INTERPOLATED_NORMAL vec3(0.0)
#endif

ReliefFrame reliefFrameOf(ReliefFragment fragment)
{
  return reliefDerivativeFrame(fragment, RELIEF_INTERPOLATED_NORMAL);
}
#undef RELIEF_INTERPOLATED_NORMAL
#endif
#endif
