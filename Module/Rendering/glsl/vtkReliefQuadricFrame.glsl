// vtkRelief: the quadric frame (Oliveira and Policarpo 2005, s3.1-3.4), for
// vtkOpenGLQuadricReliefMapper: the interpolated tangent basis (vtkReliefTangentBasis.glsl)
// with a curved reference surface. The frame interface is described in
// vtkReliefCommon.glsl; written in the GLSL subset GLM also compiles.
//
// Around a fragment the surface is the interpolated quadric z = a x^2 + b y^2 of its
// tangent frame (x along the tangent, y along the bitangent, z along the normal, world
// units; vtkLocalQuadricFilter's convention: a sphere seen from outside has a, b < 0).
// The view ray is straight, P = V t with V the unit view direction in that frame
// (V.z < 0 going in) and t the distance travelled from the fragment. The fragment lies on
// the mapper's hull, `height` above the quadric (below it where the polygons sag inside
// the surface and the hull is not lifted there); the ray starts where it meets the
// quadric (reliefQuadricEntry). Its depth below the quadric, measured along z (Eq. 7, the
// approximate distance), in relief depth units (1 = DepthScale), is D(t) = A t^2 + B t -
// height / DepthScale with A = (a V.x^2 + b V.y^2) / DepthScale and B = -V.z / DepthScale:
// quadratic in t, which a ReliefRay's bend carries, so every search that samples the ray
// (Linear, LinearBinary, Secant) follows it unchanged. Its texture coordinates move by
// (V.x / s_x, V.y / s_y) per unit t (Eq. 9).
//
// The exact distance (Eq. 5-6, compiled with RELIEF_EXACT_DISTANCE) measures from P
// along U, the unit vector perpendicular to V in the plane of V and the normal, to the
// quadric: s solves a (P.x + U.x s)^2 + b (P.y + U.y s)^2 = P.z + U.z s. Oliveira and
// Policarpo (2005) use it where both principal curvatures bend away from the viewer (here
// a, b < 0), and Eq. 7 elsewhere: where both bend toward the viewer (bowls), where the
// Gaussian curvature is negative or zero (saddles, cylinders, planes), and when V is the
// normal (U undefined).

// A vertex's quadric (a, b) in view units, from vtkLocalQuadricFilter's in model units:
// curvature is 1 / length, so an actor's scale k turns a into a / k; NaN is a plane.
vec2 reliefQuadricVertex(vec2 quadricMC, vec2 stretch)
{
  if (isnan(quadricMC.x) || isnan(quadricMC.y) || isinf(quadricMC.x) || isinf(quadricMC.y))
  {
    return vec2(0.0f, 0.0f);
  }
  return vec2(quadricMC.x / stretch.x, quadricMC.y / stretch.y);
}

#if defined(RELIEF_VERTEX_STAGE)
in vec2 reliefQuadricMC;  // (a, b) of vtkLocalQuadricFilter, model units
in float reliefHullLiftMC; // and its lift: how far the surface rises above the polygons
uniform float reliefHullClearance; // how far below the surface the relief's top lies
uniform mat4 reliefVCDCMatrix;
out vec2 reliefQuadricVSOutput;
out vec3 reliefHullOffsetVSOutput; // the hull's offset from the point, view space

// The hull: each point lifted along its model normal (the offset carried to view space as
// a direction: an actor's scale stretches it as it stretches the mesh) as far as the relief
// may rise above the polygons, the surface's rise less the relief's clearance below the
// surface. No further: a ray that starts higher runs further before it meets its quadric,
// and at grazing angles the quadric's error grows with that run.
void reliefFrameVertex()
{
  ReliefTangentVertex basis = reliefTangentBasisVertex();
  reliefQuadricVSOutput = reliefQuadricVertex(reliefQuadricMC, basis.stretch);
  bool finite = !isnan(reliefHullLiftMC) && !isinf(reliefHullLiftMC);
  vec3 along = reliefDirectionMatrix * normalize(reliefNormalMC);
  float stretch = length(along);
  float lift = finite ? max(reliefHullLiftMC * stretch - reliefHullClearance, 0.0) : 0.0;
  vec3 offset = stretch > 0.0 ? along * (lift / stretch) : vec3(0.0);
  reliefHullOffsetVSOutput = offset;
  reliefPositionVSOutput += offset;
  gl_Position += reliefVCDCMatrix * vec4(offset, 0.0);
}
#elif defined(RELIEF_GEOMETRY_STAGE)
in vec2 reliefQuadricVSOutput[];
in vec3 reliefHullOffsetVSOutput[];
out vec2 reliefQuadricGSOutput;
out vec3 reliefHullOffsetGSOutput;
out vec3 reliefBarycentricGSOutput;
flat out vec3 reliefEdgeRisesGSOutput;

// How far a corner's quadric rises along its normal over the step `edge` in its tangent
// plane, a x^2 + b y^2 (vtkLocalQuadricFilter computes the same for the lift).
float reliefQuadricRise(vec3 normal, vec3 tangent, vec2 quadric, vec3 edge)
{
  vec3 n = normalize(normal);
  vec3 t = normalize(tangent - n * dot(n, tangent));
  float x = dot(edge, t);
  float y = dot(edge, cross(n, t));
  return quadric.x * x * x + quadric.y * y * y;
}

// The surface's height over the chord from corner i to corner j is -s (1 - s) times the
// mean of both corners' rises along it; w = minus that mean. Constant indices only: an
// unsized input array takes no function argument as index.
#define reliefHullCorner(i) (reliefPositionVSOutput[i] - reliefHullOffsetVSOutput[i])
#define reliefHullEdgeRise(i, j) \
  (-0.5 * (reliefQuadricRise(reliefNormalVSOutput[i], reliefTangentVSOutput[i], \
             reliefQuadricVSOutput[i], reliefHullCorner(j) - reliefHullCorner(i)) + \
            reliefQuadricRise(reliefNormalVSOutput[j], reliefTangentVSOutput[j], \
              reliefQuadricVSOutput[j], reliefHullCorner(i) - reliefHullCorner(j))))

// Each corner its barycentric axis, the triangle its three edges' w (the edge opposite
// corner 0 first): the fragment's quadric surface stands sum l_i l_j w_ij over its polygon.
#define reliefFrameGeometry(vertex) \
  reliefTangentBasisGeometry(vertex); \
  reliefQuadricGSOutput = reliefQuadricVSOutput[vertex]; \
  reliefHullOffsetGSOutput = reliefHullOffsetVSOutput[vertex]; \
  reliefBarycentricGSOutput = vec3(equal(ivec3(vertex), ivec3(0, 1, 2))); \
  reliefEdgeRisesGSOutput = \
    vec3(reliefHullEdgeRise(1, 2), reliefHullEdgeRise(2, 0), reliefHullEdgeRise(0, 1))
#else

// The quadric's depth terms (A, B) of the view direction `view` in the tangent frame;
// a grazing ray's descent is held at 1e-3 of its run, as reliefViewRay() does.
vec2 reliefQuadricDepthTerms(vec3 view, vec2 quadric, float depthScale)
{
  float descent = max(-view.z, 1e-3f * length(vec2(view.x, view.y)));
  return vec2((quadric.x * view.x * view.x + quadric.y * view.y * view.y) / depthScale,
    max(descent, 1e-12f) / depthScale);
}

// The distance along the view ray that is searched (s3.3): to where the ray first
// reaches the deepest depth searched (1 for a height map) or, on a surface curving away
// from it, comes back to the quadric (depth 0: a ray that met nothing there passed the
// silhouette), whichever comes first.
float reliefQuadricRange(vec2 terms, float deepest)
{
  float range = 1e30f;
  if (terms.x < 0.0f)
  {
    range = -terms.y / terms.x;
  }
  float discriminant = terms.y * terms.y + 4.0f * terms.x * deepest;
  if (discriminant >= 0.0f)
  {
    range = min(range, 2.0f * deepest / (terms.y + sqrt(discriminant)));
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
  ray.exact = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  ray.screenRun = RELIEF_UNKNOWN_RUN;
  return ray;
}

// Adds the exact distance's terms to a view ray of reliefQuadricViewRay() (same view,
// quadric, DepthScale and range) that starts `entry` along the view direction from the
// fragment, above the quadric's apex (P.x, P.y = V.x, V.y (entry + t range)). With Q =
// a P.x^2 + b P.y^2 - P.z = DepthScale D (the vertical depth D in depth units), A =
// a U.x^2 + b U.y^2 and B = 2 (a P.x U.x + b P.y U.y) - U.z, Eq. 6's root is s = 2 Q /
// (-B + sqrt(B^2 - 4 A Q)), written so that it holds as A goes to 0; B is linear in t.
ReliefRay reliefQuadricExact(ReliefRay ray, vec3 view, vec2 quadric, float depthScale,
  float entry, float range)
{
  float sine = sqrt(max(1.0f - view.z * view.z, 0.0f));
  ray.exact = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  // both curvatures bending away, the lesser at least 1e-3 of the greater (a fitted
  // cylinder's axis term is zero only up to rounding)
  if (max(quadric.x, quadric.y) < 1e-3f * min(quadric.x, quadric.y) && sine > 1e-4f)
  {
    vec3 u = vec3(-view.x * view.z / sine, -view.y * view.z / sine, sine);
    float a = quadric.x * u.x * u.x + quadric.y * u.y * u.y;
    float along = 2.0f * (quadric.x * view.x * u.x + quadric.y * view.y * u.y);
    ray.exact = vec4(along * range, along * entry - u.z, 4.0f * a * depthScale, 1.0f);
  }
  return ray;
}

#ifdef RELIEF_EXACT_DISTANCE
// The ray's depth at t by Eq. 6 where its terms are set, from its vertical depth
float reliefExactDepth(ReliefRay ray, float t, float verticalDepth)
{
  if (ray.exact.w < 0.5f)
  {
    return verticalDepth;
  }
  float b = ray.exact.x * t + ray.exact.y;
  float discriminant = b * b - ray.exact.z * verticalDepth;
  return discriminant >= 0.0f && b < 0.0f
    ? 2.0f * verticalDepth / (sqrt(discriminant) - b)
    : verticalDepth;
}
#endif

// True when a back face's fragment lies behind an outline that the front faces carve.
// `terms` are the depth terms of the view ray followed back from the fragment toward the
// viewer, below the surface's outward quadric (reliefQuadricDepthTerms of the back face's
// view direction with the quadric as the front side sees it). When that backward ray
// comes back out of the quadric before it reaches `deepest` (the depth searched, 1 for a
// height map), and before it reaches the
// viewer (`eyeDistance` away along it, world units), the view ray came in through the
// curved surface close by, and the front side's relief answers for this pixel: seen from
// there it meets the relief or leaves past the outline. Otherwise the ray arrives from
// inside the shape (the inside of an open shell, or a viewer within the shape) and the
// back face is what it sees.
bool reliefQuadricBehindOutline(vec2 terms, float deepest, float eyeDistance)
{
  return terms.x < 0.0f && terms.y * terms.y + 4.0f * terms.x * deepest < 0.0f &&
    -terms.y / terms.x < eyeDistance;
}

// True when a ray that met nothing ended back on the quadric, not at the deepest depth
// searched: it left the surface past the silhouette, and the fragment shows what lies
// behind.
bool reliefQuadricLeaves(ReliefRay ray, float deepest)
{
  return reliefRayAt(ray, 1.0f).z < 0.5f * deepest;
}

// Where the view ray from a point `height` above the quadric (depth units, negative
// below it) first meets it: A t^2 + B t = height, its root 2 height / (B + sqrt(B^2 +
// 4 A height)) written so that it holds as A goes to 0. x: that distance; y, z: the
// depth terms from there on, (A, B + 2 A t) = (A, sqrt(B^2 + 4 A height)); w: 0 where
// the ray passes above a quadric that bends away, meeting nothing (below a bowl whose
// surface it never crosses, it starts where it is, -height deep: reliefFrameViewRay).
vec4 reliefQuadricEntry(vec2 terms, float height)
{
  float discriminant = terms.y * terms.y + 4.0f * terms.x * height;
  if (discriminant < 0.0f)
  {
    return vec4(0.0f, terms.x, terms.y, height > 0.0f ? 0.0f : 1.0f);
  }
  float root = sqrt(discriminant);
  return vec4(2.0f * height / (terms.y + root), terms.x, max(root, 1e-12f), 1.0f);
}

struct ReliefFrame
{
  vec3 axisU;
  vec3 axisV;
  vec3 normal;
  bool usable;
  vec3 tangent;   // the quadric's x and y axes, view space
  vec3 bitangent;
  vec2 textureScale;
  vec2 quadric;   // (a, b) as the side seen bends: turned for a back face
  vec2 outward;   // (a, b) as the front side bends, for the back-face test
  vec3 view;      // the unit view direction in the frame (x, y, z: tangent, bitangent, normal)
  float height;   // the fragment's point above the quadric of the side seen, world units
  bool meets;     // the view ray meets the quadric
  float entry;    // the distance along it to where it does (world units, < 0 behind)
  vec2 terms;     // the depth terms from there on
  float depth;    // the ray's depth there: 0 on the quadric, -height below a bowl it never crosses
  float range;    // and the distance searched from there (reliefQuadricRange)
  float deepest;  // to the fragment's deepest depth
};

// The frame at a fragment whose point lies `height` above the quadric surface along the
// normal, as the front side sees it (the hull's: vtkOpenGLQuadricReliefMapper).
ReliefFrame reliefQuadricFrame(
  ReliefTangentBasis basis, vec2 quadric, float height, ReliefFragment fragment)
{
  ReliefFrame frame;
  frame.axisU = basis.tangent / basis.textureScale.x;
  frame.axisV = basis.bitangent / basis.textureScale.y;
  frame.normal = basis.normal;
  frame.usable = true;
  frame.tangent = basis.tangent;
  frame.bitangent = basis.bitangent;
  frame.textureScale = basis.textureScale;
  frame.outward = quadric;
  frame.quadric = fragment.frontFacing ? quadric : -quadric;
  frame.view = vec3(dot(fragment.viewVC, basis.tangent), dot(fragment.viewVC, basis.bitangent),
    dot(fragment.viewVC, basis.normal));
  frame.height = fragment.frontFacing ? height : -height;
  vec4 entry = reliefQuadricEntry(
    reliefQuadricDepthTerms(frame.view, frame.quadric, fragment.depthScale),
    frame.height / fragment.depthScale);
  frame.meets = entry.w > 0.5f;
  frame.entry = entry.x;
  frame.depth = frame.height < 0.0f && entry.x == 0.0f ? -frame.height / fragment.depthScale : 0.0f;
  frame.terms = vec2(entry.y, entry.z);
  frame.deepest = fragment.deepest;
  frame.range = reliefQuadricRange(frame.terms, frame.deepest);
  return frame;
}

// A front fragment whose ray passes above the quadric lies outside the outline; a back
// face draws relief only where the ray reaches it from inside the shape.
bool reliefFrameHides(ReliefFrame frame, ReliefFragment fragment)
{
  if (fragment.frontFacing || fragment.twoSided)
  {
    return !frame.meets;
  }
  return reliefQuadricBehindOutline(
    reliefQuadricDepthTerms(frame.view, frame.outward, fragment.depthScale), frame.deepest,
    fragment.eyeDistance);
}

// The straight view ray below the quadric, from where it meets it over the range that is
// searched; one that meets nothing rises from the fragment's point (it leaves at once).
ReliefRay reliefFrameViewRay(ReliefFrame frame, ReliefFragment fragment)
{
  vec2 entryUV = fragment.tcoord +
    frame.entry * vec2(frame.view.x / frame.textureScale.x, frame.view.y / frame.textureScale.y);
  ReliefRay ray =
    reliefQuadricViewRay(entryUV, frame.view, frame.textureScale, frame.terms, frame.range);
  ray.origin.z = frame.depth;
#ifdef RELIEF_EXACT_DISTANCE
  ray = reliefQuadricExact(
    ray, frame.view, frame.quadric, fragment.depthScale, frame.entry, frame.range);
#endif
  if (!frame.meets)
  {
    ray.origin = vec3(fragment.tcoord.x, fragment.tcoord.y, 0.0f);
    ray.direction = vec3(0.0f, 0.0f, -1.0f);
    ray.bend = 0.0f;
    ray.exact = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  }
  return ray;
}

bool reliefFrameRayLeft(ReliefFrame frame, ReliefRay ray, ReliefHit hit)
{
  return !hit.hit && reliefQuadricLeaves(ray, frame.deepest);
}

float reliefFrameHitDistance(ReliefFrame frame, ReliefFragment fragment, ReliefRay ray,
  ReliefHit hit)
{
  return frame.entry + hit.t * frame.range;
}

// The quadric's slope at the point `distance` along the view ray, in view space.
vec3 reliefFrameSurfaceSlope(ReliefFrame frame, ReliefFragment fragment, float distance)
{
  float slopeX = -2.0f * frame.quadric.x * frame.view.x * distance;
  float slopeY = -2.0f * frame.quadric.y * frame.view.y * distance;
  return frame.tangent * slopeX + frame.bitangent * slopeY;
}

#if defined(RELIEF_FRAGMENT_STAGE)
in vec2 reliefQuadricVSOutput;
in vec3 reliefHullOffsetVSOutput;
in vec3 reliefBarycentricVSOutput;
flat in vec3 reliefEdgeRisesVSOutput;

// The fragment's height above the quadric surface along the front side's unit normal:
// the hull's lift there less the surface's rise over the polygon, sum l_i l_j w_ij.
float reliefHullHeight(vec3 frontNormal)
{
  vec3 l = reliefBarycentricVSOutput;
  return dot(reliefHullOffsetVSOutput, frontNormal) -
    dot(l.yzx * l.zxy, reliefEdgeRisesVSOutput);
}

ReliefFrame reliefFrameOf(ReliefFragment fragment)
{
  ReliefTangentBasis basis = reliefTangentBasisOf(fragment);
  vec3 frontNormal = fragment.frontFacing ? basis.normal : -basis.normal;
  return reliefQuadricFrame(
    basis, reliefQuadricVSOutput, reliefHullHeight(frontNormal), fragment);
}
#endif
#endif
