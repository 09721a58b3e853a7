// vtkRelief: a fragment's texture-space axes from screen-space derivatives (seed 003,
// "Texture coordinate offset calculations"), for meshes without tangents.
//
// Written in the GLSL subset GLM also compiles (see vtkReliefCommon.glsl): the unit
// tests check it on the CPU against triangles' exact texture mappings.

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
// coordinates; seed 003 projects on normalized dFdx and dFdy instead, which holds only
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
