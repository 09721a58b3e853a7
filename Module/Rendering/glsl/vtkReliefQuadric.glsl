// vtkRelief: the view ray of the quadric frame (Oliveira and Policarpo 2005, s3.1-3.4),
// for vtkOpenGLQuadricReliefMapper. Shared with the CPU mirror; see vtkReliefCommon.glsl
// for the rules.
//
// Around a fragment the surface is the interpolated quadric z = a x^2 + b y^2 of its
// tangent frame (x along the tangent, y along the bitangent, z along the normal, world
// units; vtkLocalQuadricFilter's convention: a sphere seen from outside has a, b < 0).
// The view ray is straight, P = V t with V the unit view direction in that frame
// (V.z < 0 going in) and t the distance travelled. Its depth below the quadric,
// measured along z (Eq. 7, the approximate distance), in relief depth units (1 =
// DepthScale), is D(t) = A t^2 + B t with A = (a V.x^2 + b V.y^2) / DepthScale and
// B = -V.z / DepthScale: quadratic in t, which a ReliefRay's bend carries, so every
// search that samples the ray (Linear, LinearBinary, Secant) follows it unchanged. Its
// texture coordinates move by (V.x / s_x, V.y / s_y) per unit t (Eq. 9).

// The quadric's depth terms (A, B) of the view direction `view` in the tangent frame;
// a grazing ray's descent is held at 1e-3 of its run, as reliefViewRay() does.
vec2 reliefQuadricDepthTerms(vec3 view, vec2 quadric, float depthScale)
{
  float descent = max(-view.z, 1e-3f * length(vec2(view.x, view.y)));
  return vec2((quadric.x * view.x * view.x + quadric.y * view.y * view.y) / depthScale,
    max(descent, 1e-12f) / depthScale);
}

// The distance along the view ray that is searched (s3.3): to where the ray first
// reaches depth 1 or, on a surface curving away from it, comes back to the quadric
// (depth 0: a ray that met nothing there passed the silhouette), whichever comes first.
float reliefQuadricRange(vec2 terms)
{
  float range = 1e30f;
  if (terms.x < 0.0f)
  {
    range = -terms.y / terms.x;
  }
  float discriminant = terms.y * terms.y + 4.0f * terms.x;
  if (discriminant >= 0.0f)
  {
    range = min(range, 2.0f / (terms.y + sqrt(discriminant)));
  }
  return range;
}

// The view ray over [0, range], t in [0, 1] of the ray standing for distance t range.
ReliefRay reliefQuadricViewRay(vec2 entryUV, vec3 view, vec2 scale, vec2 terms, float range)
{
  ReliefRay ray;
  ray.origin = vec3(entryUV.x, entryUV.y, 0.0f);
  ray.direction = vec3(view.x / scale.x * range, view.y / scale.y * range, terms.y * range);
  ray.bend = terms.x * range * range;
  return ray;
}

// True when a ray that met nothing ended back on the quadric, not at depth 1: it left
// the surface past the silhouette, and the fragment shows what lies behind.
bool reliefQuadricLeaves(ReliefRay ray)
{
  return reliefRayAt(ray, 1.0f).z < 0.5f;
}
