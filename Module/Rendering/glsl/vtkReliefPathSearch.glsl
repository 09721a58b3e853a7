// vtkRelief: the path-feature search (the path-feature paper, seed 004, s5): the view ray
// walks the cells of vtkPathFeatureTextureFilter's grid (Algorithm 1), skips a cell it
// passes over above the cell's highest feature, and in the others finds where it first
// enters solid matter: the base surface, minus what the features' profiles cut below it,
// plus what they add above it (CSG, s5.3), the highest priority deciding where features
// of different priorities overlap, cuts winning among equals. Shared with the CPU
// mirror; see vtkReliefCommon.glsl for the rules.
//
// An element is a segment swept by its path's profile: across it, x = the signed distance
// to its line in half widths (right positive), y = depth below the base; both scaled by
// the path's perturbation, linear along the path (s5.5). Beyond its two ends the profile
// is revolved about the end point (each half on its own side), so that a path's elements
// join without gaps and a path ends round (s5.4): the union of the elements is the profile
// swept along the whole path. Where the path goes on exactly straight (the pieces of a
// split segment, ExactJointRadians) the element ends at the plane across its end
// instead, its neighbour's straight part going on: that is the sweep (a profile whose
// inside does not reach its middle at some depth would bulge there, revolved), and a ray
// that passes the joint meets no revolved facet. So it does where the path turns and one
// of the two revolved ends holds all the other does (the filter's RevolvedOnce: a centred
// profile, one scale): only that one is revolved. Each profile facet, with the
// perturbation's linear scale, is met by a straight ray where a linear function of t
// vanishes (s5.2), each revolved facet where a quadratic does.
//
// The includer defines RELIEF_PATH_TEXEL(index), texel `index` (int) of the data texture,
// and RELIEF_PATH_CELL(cell), the grid texel of cell (vec2, whole numbers, repeating).
// Results besides the ReliefHit: reliefPathHitNormal, the outward normal at the hit as a
// covector in (u, v, depth) (a texture-space direction w leaves the solid where
// dot(normal, w) > 0), reliefPathHitMaterial, the material's data texel, or -1 for the
// actor's property, and reliefPathNearest, the feature the walk came closest to (region
// sampling's, reliefPathRegions).

// The most elements of a cell (vtkPathFeatureTextureFilter::CellCapacity), points of a
// profile (MaximumProfilePoints) and crossings tried per cell.
#define RELIEF_PATH_CELL_CAPACITY 32
#define RELIEF_PATH_PROFILE_POINTS 64
#define RELIEF_PATH_EVENTS 96
// A cut's opening is where its profile's inside lies this far below the base (a profile
// point rounded to just below the base, sin(pi), opens no other wall than one at 0).
#define RELIEF_PATH_OPENING 1e-6f

vec3 reliefPathHitNormal;
float reliefPathHitMaterial;

// The element a ray came closest to, and how close it and any other came, in (u, v): the
// least reliefPathGap of the elements listed where it passed below a cell's top; 1e30
// where none. The elements of its path that go on from it without a corner (its joins,
// vtkPathFeatureTextureFilter::SmoothJointDegrees) are one feature with it, not others.
struct ReliefPathNearest
{
  float gap;
  int element; // its data texel; -1 where none
  int joins;   // 1: its path's previous element goes on from its start, 2: the next from its end
               // (+ 4, + 8: its start, its end is not revolved: vtkPathFeatureTextureFilter)
  vec2 near;   // where the ray passed it (the copy of the tile it is in)
  float second; // the least gap of the other elements
};

ReliefPathNearest reliefPathNoneNear()
{
  ReliefPathNearest nearest;
  nearest.gap = 1e30f;
  nearest.element = -1;
  nearest.joins = 0;
  nearest.near = vec2(0.0f, 0.0f);
  nearest.second = 1e30f;
  return nearest;
}

// Whether `element` (a data texel) is the nearest or one that goes on from it (the
// data's elements of a path are two texels apart).
bool reliefPathSameFeature(ReliefPathNearest nearest, int element)
{
  return element >= 0 &&
    (element == nearest.element || (element == nearest.element + 2 && (nearest.joins & 2) != 0) ||
      (element == nearest.element - 2 && (nearest.joins & 1) != 0));
}

// `nearest` with element's gap near `near` counted (-1: an element other than nearest's).
// The nearest element or one that goes on from it takes its place where nearer, and is no
// second.
ReliefPathNearest reliefPathNearer(
  ReliefPathNearest nearest, float gap, int element, int joins, vec2 near)
{
  if (reliefPathSameFeature(nearest, element))
  {
    if (gap < nearest.gap)
    {
      nearest.gap = gap;
      nearest.element = element;
      nearest.joins = joins;
      nearest.near = near;
    }
  }
  else if (gap < nearest.gap)
  {
    nearest.second = nearest.gap;
    nearest.gap = gap;
    nearest.element = element;
    nearest.joins = joins;
    nearest.near = near;
  }
  else
  {
    nearest.second = min(nearest.second, gap);
  }
  return nearest;
}

// The nearest of the last walk.
ReliefPathNearest reliefPathNearest;

// One element, placed in the copy of the tile the walk is in.
struct ReliefPathElement
{
  vec2 start;
  vec2 end;
  vec2 axis;       // unit, start to end
  vec2 right;      // unit, the right side's normal
  float span;      // length
  float halfWidth;
  float scaleStart; // the perturbation at start and end
  float scaleEnd;
  int profile;     // the profile's first point's texel
  int points;
  float extent;    // the most |x| of the profile
  float top;       // its least y (above the base where negative)
  float bottom;    // its deepest y
  float material;
  float priority;
  int joins;       // ReliefPathNearest's
  int rounded;     // 1: the profile is revolved about its start, 2: about its end (not
                   // where joins says so; at both ends of an element alone)
  bool centred;    // the profile holds one interval centred on x = 0 at every depth
};

// Whether the element's profile both cuts below the base and adds above it.
bool reliefPathMixes(ReliefPathElement element)
{
  return element.top < 0.0f && element.bottom > 0.0f;
}

ReliefPathElement reliefPathElement(int texel, vec2 near)
{
  vec4 ends = RELIEF_PATH_TEXEL(texel);
  vec4 record = RELIEF_PATH_TEXEL(texel + 1);
  int pathTexel = int(record.x);
  vec4 path = RELIEF_PATH_TEXEL(pathTexel);
  vec4 scales = RELIEF_PATH_TEXEL(pathTexel + 1);
  vec4 profile = RELIEF_PATH_TEXEL(int(path.y));
  ReliefPathElement element;
  element.start = vec2(ends.x, ends.y);
  element.end = vec2(ends.z, ends.w);
  // the copy nearest to the cell: elements are at most a quarter tile long
  vec2 shift = round(near - 0.5f * (element.start + element.end));
  element.start += shift;
  element.end += shift;
  vec2 along = element.end - element.start;
  element.span = max(length(along), 1e-30f);
  element.axis = along / element.span;
  element.right = vec2(element.axis.y, -element.axis.x);
  element.halfWidth = path.x;
  float pathLength = max(scales.z, 1e-30f);
  element.scaleStart = mix(scales.x, scales.y, record.y / pathLength);
  element.scaleEnd = mix(scales.x, scales.y, record.z / pathLength);
  element.profile = int(path.y) + 1;
  element.points = min(int(profile.x), RELIEF_PATH_PROFILE_POINTS);
  element.extent = profile.y;
  element.top = profile.z;
  element.bottom = profile.w;
  element.material = path.z;
  element.priority = path.w;
  element.joins = int(record.w);
  element.rounded = 3 & ~(element.joins >> 2);
  element.centred = scales.w < 0.5f;
  return element;
}

// Whether a ray from (x, y) toward +x crosses the profile's segment from a to b: 1 or 0.
int reliefPathCrosses(vec2 a, vec2 b, float x, float y)
{
  if ((b.y > y) == (a.y > y))
  {
    return 0;
  }
  return x < b.x + (y - b.y) * (a.x - b.x) / (a.y - b.y) ? 1 : 0;
}

// Point k of a profile from the texel that holds it (`pair`: points are two a texel, the
// texel of k / 2).
vec2 reliefPathPairPoint(vec4 pair, int k)
{
  return k % 2 == 0 ? vec2(pair.x, pair.y) : vec2(pair.z, pair.w);
}

// The last point of the element's profile, from which the profile closes to its first.
vec2 reliefPathLastPoint(ReliefPathElement element)
{
  return reliefPathPairPoint(
    RELIEF_PATH_TEXEL(element.profile + (element.points - 1) / 2), element.points - 1);
}

// Whether (x, y0) and (x, y1) lie inside the profile closed by its last-to-first segment
// (even-odd): bits 1 and 2. Its points are read two a texel.
int reliefPathInsideProfile(ReliefPathElement element, float x, float y0, float y1)
{
  int crossings0 = 0;
  int crossings1 = 0;
  vec2 previous = reliefPathLastPoint(element);
  for (int k = 0; k < RELIEF_PATH_PROFILE_POINTS && k < element.points; k += 2)
  {
    vec4 pair = RELIEF_PATH_TEXEL(element.profile + k / 2);
    vec2 point = vec2(pair.x, pair.y);
    crossings0 += reliefPathCrosses(previous, point, x, y0);
    crossings1 += reliefPathCrosses(previous, point, x, y1);
    previous = point;
    if (k + 1 < element.points)
    {
      point = vec2(pair.z, pair.w);
      crossings0 += reliefPathCrosses(previous, point, x, y0);
      crossings1 += reliefPathCrosses(previous, point, x, y1);
      previous = point;
    }
  }
  return (crossings0 % 2) + 2 * (crossings1 % 2);
}

// The profile coordinates (x, y) of a point, and the scale there (z); z = 0 where the
// feature has narrowed to nothing, or beyond an end that is not revolved.
vec3 reliefPathProfileAt(ReliefPathElement element, vec3 point, float base)
{
  vec2 offset = vec2(point.x, point.y) - element.start;
  float along = dot(offset, element.axis);
  float across = dot(offset, element.right);
  float scale =
    mix(element.scaleStart, element.scaleEnd, clamp(along / element.span, 0.0f, 1.0f));
  if (along < 0.0f || along > element.span)
  {
    if ((element.rounded & (along < 0.0f ? 1 : 2)) == 0)
    {
      return vec3(0.0f, 0.0f, 0.0f); // not revolved: its neighbour holds what goes on
    }
    // the revolved end: the distance to the end point, on the side the point is
    vec2 centre = along < 0.0f ? element.start : element.end;
    float side = across >= 0.0f ? 1.0f : -1.0f;
    across = side * length(vec2(point.x, point.y) - centre);
  }
  if (!(scale > 1e-6f))
  {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  return vec3(across / (element.halfWidth * scale), (point.z - base) / scale, scale);
}

// What an element makes of a point: 0 nothing, 1 added matter, 2 a cut (which reaches up
// through everything above its opening, s5.3).
int reliefPathElementClass(ReliefPathElement element, vec3 point, float base)
{
  vec3 profile = reliefPathProfileAt(element, point, base);
  if (profile.z == 0.0f || abs(profile.x) > element.extent || profile.y > element.bottom)
  {
    return 0;
  }
  // below the base, the profile's inside is cut; above it, its inside is added, and above
  // its opening the cut goes on up
  float y = profile.y >= 0.0f ? max(profile.y, RELIEF_PATH_OPENING) : profile.y;
  int inside = reliefPathInsideProfile(element, profile.x, y, RELIEF_PATH_OPENING);
  if (profile.y >= 0.0f)
  {
    return inside % 2 == 1 ? 2 : 0;
  }
  return inside % 2 == 1 ? 1 : (inside >= 2 ? 2 : 0);
}

// Component `slot` of a texel.
float reliefPathEntry(vec4 entries, int slot)
{
  return slot == 0 ? entries.x : (slot == 1 ? entries.y : (slot == 2 ? entries.z : entries.w));
}

// The data texel of element k of a cell's list, four a texel; a list of -e is element e
// alone.
int reliefPathListed(int list, int k)
{
  if (list < 0)
  {
    return -list;
  }
  return int(reliefPathEntry(RELIEF_PATH_TEXEL(list + k / 4), k - 4 * (k / 4)));
}

// Element `texel`, from its start to its end.
vec2 reliefPathRun(int texel)
{
  vec4 ends = RELIEF_PATH_TEXEL(texel);
  return vec2(ends.z - ends.x, ends.w - ends.y);
}

// The length of element `texel`.
float reliefPathSpan(int texel)
{
  return length(reliefPathRun(texel));
}

// How far the outline of element `texel` and the next of its path strays from the first
// one's, straight on, up to `past` beyond their joint, where the profile reaches
// `halfExtent` either side: the next one's edge on the inside of the turn leans out by
// the turn, from halfExtent tan(turn / 2) before the joint, where it crosses the first
// one's, and lies halfExtent (1 / cos - 1) out at the joint (outside the turn the ends'
// revolved profiles fill in, less far); none where the rays stop short of all that.
float reliefPathStray(int texel, float past, float halfExtent)
{
  vec2 axis = normalize(reliefPathRun(texel));
  vec2 nextAxis = normalize(reliefPathRun(texel + 2));
  float sine = abs(axis.x * nextAxis.y - axis.y * nextAxis.x);
  float cosine = max(dot(axis, nextAxis), 1e-3f);
  float lead = halfExtent * sine / (1.0f + cosine);
  float leaning = sine * (max(past, 0.0f) + lead) + halfExtent * (1.0f - cosine);
  return past + lead > 0.0f ? leaning / cosine : 0.0f;
}

// Element `texel` of a cell's list, placed near `near`. Element e alone (a list of -e:
// region sampling's, reliefPathRegions) goes on straight through its joins, as
// far as the elements there reach, the perturbation's scale going on as along its path
// (reliefPathRegions judges where the path's turn there strays too far from that).
ReliefPathElement reliefPathListedElement(int list, int texel, vec2 near)
{
  ReliefPathElement element = reliefPathElement(texel, near);
  if (list < 0)
  {
    float before = (element.joins & 1) != 0 ? reliefPathSpan(texel - 2) : 0.0f;
    float after = (element.joins & 2) != 0 ? reliefPathSpan(texel + 2) : 0.0f;
    float slope = (element.scaleEnd - element.scaleStart) / element.span;
    element.start -= before * element.axis;
    element.end += after * element.axis;
    element.scaleStart = max(element.scaleStart - slope * before, 0.0f);
    element.scaleEnd = max(element.scaleEnd + slope * after, 0.0f);
    element.span += before + after;
    element.rounded = 3;
  }
  return element;
}

// The next crossing of a surface after `after`, with its normal and material.
struct ReliefPathEvent
{
  float t;
  vec3 normal; // the gradient of the function that vanishes there, in (u, v, depth)
  float material;
};

ReliefPathEvent reliefPathKeep(
  ReliefPathEvent best, float t, float after, vec3 normal, float material)
{
  if (t > after && t < best.t)
  {
    best.t = t;
    best.normal = normal;
    best.material = material;
  }
  return best;
}

// The roots of a t^2 + b t + c, low then high (-1e30 where there are none).
vec2 reliefPathRoots(float a, float b, float c)
{
  if (abs(a) < 1e-12f * (abs(b) + abs(c)))
  {
    float root = abs(b) > 0.0f ? -c / b : -1e30f;
    return vec2(root, root);
  }
  float discriminant = b * b - 4.0f * a * c;
  if (discriminant < -1e-5f * b * b)
  {
    return vec2(-1e30f, -1e30f);
  }
  // a double root rounded below zero (a ray down a revolved end's axis) still crosses
  discriminant = max(discriminant, 0.0f);
  float q = -0.5f * (b >= 0.0f ? b + sqrt(discriminant) : b - sqrt(discriminant));
  float r1 = q / a;
  float r2 = q != 0.0f ? c / q : r1;
  return vec2(min(r1, r2), max(r1, r2));
}

// Whether the ray point at t lies on the facet from p0 to p1 of the element's profile
// (within the facet's span) revolved about the element's start (end -1) or end (+1).
bool reliefPathOnFacet(ReliefPathElement element, ReliefRay ray, float t, float base, vec2 p0,
  vec2 p1, float end)
{
  vec3 point = reliefRayAt(ray, t);
  vec2 offset = vec2(point.x, point.y) - element.start;
  float along = dot(offset, element.axis);
  float part = along < 0.0f ? -1.0f : (along > element.span ? 1.0f : 0.0f);
  if (part != end)
  {
    return false;
  }
  vec3 profile = reliefPathProfileAt(element, point, base);
  if (profile.z == 0.0f)
  {
    return false;
  }
  vec2 facet = p1 - p0;
  vec2 from = vec2(profile.x, profile.y) - p0;
  float facetLength = length(facet);
  float lambda = dot(from, facet) / (facetLength * facetLength);
  // on the facet's line (a revolved end's root may hold the other half's x)
  float apart = abs(from.x * facet.y - from.y * facet.x) / facetLength;
  return lambda >= -1e-4f && lambda <= 1.0f + 1e-4f && apart <= 1e-3f;
}

// The ray as one element's straight part sees it: at t, in homogeneous profile
// coordinates (across / half width, depth below the base, scale) = h0 + t h1, the profile
// point (x, y) being (h.x, h.y) / h.z. The perturbation's scale is linear along the
// element, so the ray stays a straight line in the profile's plane: `line` = h0 x h1, on
// whose sides the profile's points lie, and which crosses a facet exactly where the
// facet's two ends lie on its two sides (so that facets that share a point share its
// side: no crossing is lost or counted twice where the ray passes a profile point).
// along0 + t along1 is the distance along the element.
struct ReliefPathSweep
{
  vec3 h0;
  vec3 h1;
  vec3 line;
  float along0;
  float along1;
  float slope; // the scale's change per distance along
};

ReliefPathSweep reliefPathSweepOf(ReliefPathElement element, ReliefRay ray, float base)
{
  vec2 offset = vec2(ray.origin.x, ray.origin.y) - element.start;
  vec2 run = vec2(ray.direction.x, ray.direction.y);
  ReliefPathSweep sweep;
  sweep.slope = (element.scaleEnd - element.scaleStart) / element.span;
  sweep.along0 = dot(offset, element.axis);
  sweep.along1 = dot(run, element.axis);
  sweep.h0 = vec3(dot(offset, element.right) / element.halfWidth, ray.origin.z - base,
    element.scaleStart + sweep.slope * sweep.along0);
  sweep.h1 = vec3(
    dot(run, element.right) / element.halfWidth, ray.direction.z, sweep.slope * sweep.along1);
  sweep.line = cross(sweep.h0, sweep.h1);
  return sweep;
}

// Which side of the sweep's line the profile point p lies on.
bool reliefPathSide(ReliefPathSweep sweep, vec2 p)
{
  return sweep.line.x * p.x + sweep.line.y * p.y + sweep.line.z > 0.0f;
}

// Where the ray crosses the straight part's facet from a to b, whose ends lie on the two
// sides of the sweep's line (s5.2): the facet's line F = (a, 1) x (b, 1) vanishes on
// h0 + t h1. Kept where it is on the straight part, after `after` and before best.t, with
// the gradient of F's function of (u, v, depth) as its normal.
ReliefPathEvent reliefPathStraightCrossing(ReliefPathEvent best, ReliefPathElement element,
  ReliefPathSweep sweep, vec2 a, vec2 b, float after)
{
  vec3 facet = cross(vec3(a.x, a.y, 1.0f), vec3(b.x, b.y, 1.0f));
  float rate = dot(facet, sweep.h1);
  if (rate == 0.0f)
  {
    return best;
  }
  float t = -dot(facet, sweep.h0) / rate;
  float along = sweep.along0 + t * sweep.along1;
  if (t > after && t < best.t && along >= 0.0f && along <= element.span &&
    sweep.h0.z + t * sweep.h1.z > 0.0f)
  {
    vec2 across = (facet.x / element.halfWidth) * element.right +
      (facet.z * sweep.slope) * element.axis;
    best = reliefPathKeep(best, t, after, vec3(across.x, across.y, facet.y), element.material);
  }
  return best;
}

// The first crossing after `after` of the ray with the element's facet p0-p1 revolved
// about its start (end -1) or its end (+1), a quadratic in t, before best.t.
ReliefPathEvent reliefPathRevolvedEvents(ReliefPathEvent best, ReliefPathElement element,
  ReliefRay ray, float base, vec2 p0, vec2 p1, float after, int end)
{
  vec2 facet = p1 - p0;
  vec2 run = vec2(ray.direction.x, ray.direction.y);
  float depth0 = ray.origin.z - base;
  float depth1 = ray.direction.z;
  float w = element.halfWidth;
  vec2 centre = end < 0 ? element.start : element.end;
  float scale = end < 0 ? element.scaleStart : element.scaleEnd;
  vec2 q0 = vec2(ray.origin.x, ray.origin.y) - centre;
  float radius = w * scale;
  if (!(radius > 0.0f) || dot(facet, facet) == 0.0f)
  {
    return best;
  }
  // r^2 = (w s x)^2, x = g0 + g1 t along the facet; a level facet: the ray's depth alone
  bool level = facet.y == 0.0f;
  float g0 = level ? 0.0f : p0.x + facet.x * (depth0 / scale - p0.y) / facet.y;
  float g1 = level ? 0.0f : facet.x * depth1 / (scale * facet.y);
  vec2 roots = level ? vec2(depth1 != 0.0f ? (p0.y * scale - depth0) / depth1 : -1e30f)
                     : reliefPathRoots(dot(run, run) - radius * radius * g1 * g1,
                         2.0f * (dot(q0, run) - radius * radius * g0 * g1),
                         dot(q0, q0) - radius * radius * g0 * g0);
  for (int k = 0; k < 2; ++k)
  {
    float t = k == 0 ? roots.x : roots.y;
    if (t > after && t < best.t &&
      reliefPathOnFacet(element, ray, t, base, p0, p1, float(end)))
    {
      vec3 point = reliefRayAt(ray, t);
      vec2 from = vec2(point.x, point.y) - centre;
      float x = g0 + g1 * t;
      // F = (w s x)^2 - r^2
      vec3 normal = level ? vec3(0.0f, 0.0f, 1.0f)
                          : vec3(-2.0f * from.x, -2.0f * from.y,
                              2.0f * radius * radius * x * facet.x / (scale * facet.y));
      best = reliefPathKeep(best, t, after, normal, element.material);
    }
  }
  return best;
}

// The walls up from the cut's opening at profile x = opening (s5.3): where the ray, above
// the base, crosses x = opening.
ReliefPathEvent reliefPathWallEvents(ReliefPathEvent best, ReliefPathElement element,
  ReliefRay ray, float base, float opening, float after)
{
  vec2 offset = vec2(ray.origin.x, ray.origin.y) - element.start;
  vec2 run = vec2(ray.direction.x, ray.direction.y);
  float slope = (element.scaleEnd - element.scaleStart) / element.span;
  float w = element.halfWidth;
  float c0 = dot(offset, element.right) -
    w * opening * (element.scaleStart + slope * dot(offset, element.axis));
  float c1 = dot(run, element.right) - w * opening * slope * dot(run, element.axis);
  if (c1 != 0.0f)
  {
    float t = -c0 / c1;
    vec3 point = reliefRayAt(ray, t);
    float along = dot(vec2(point.x, point.y) - element.start, element.axis);
    if (point.z < base && along >= 0.0f && along <= element.span)
    {
      best = reliefPathKeep(best, t, after,
        vec3(element.right.x - w * opening * slope * element.axis.x,
          element.right.y - w * opening * slope * element.axis.y, 0.0f),
        element.material);
    }
  }
  float alongAfter = dot(offset, element.axis) + after * dot(run, element.axis);
  float alongBest = dot(offset, element.axis) + best.t * dot(run, element.axis);
  for (int end = -1; end <= 1; end += 2)
  {
    if ((end < 0 && min(alongAfter, alongBest) >= 0.0f) ||
      (end > 0 && max(alongAfter, alongBest) <= element.span) ||
      (element.rounded & (end < 0 ? 1 : 2)) == 0)
    {
      continue; // the ray stays beside the element's straight part; an end not revolved
    }
    vec2 centre = end < 0 ? element.start : element.end;
    float radius = w * (end < 0 ? element.scaleStart : element.scaleEnd) * abs(opening);
    vec2 q0 = vec2(ray.origin.x, ray.origin.y) - centre;
    vec2 roots = reliefPathRoots(dot(run, run), 2.0f * dot(q0, run), dot(q0, q0) - radius * radius);
    for (int k = 0; k < 2; ++k)
    {
      float t = k == 0 ? roots.x : roots.y;
      vec3 point = reliefRayAt(ray, t);
      vec2 from = vec2(point.x, point.y) - element.start;
      float along = dot(from, element.axis);
      float across = dot(from, element.right);
      bool beyond = end < 0 ? along < 0.0f : along > element.span;
      if (point.z < base && beyond && (across >= 0.0f) == (opening >= 0.0f))
      {
        vec2 outward = vec2(point.x, point.y) - centre;
        best = reliefPathKeep(best, t, after, vec3(outward.x, outward.y, 0.0f), element.material);
      }
    }
  }
  return best;
}

// How far the ray between t0 and t1 stays from the element's reach (its profile's extent,
// at its largest scale) in (u, v): a lower bound, from both ends' distances across and
// along; 0 or less where it may come within reach.
float reliefPathGap(ReliefPathElement element, ReliefRay ray, float t0, float t1)
{
  float reach =
    element.halfWidth * element.extent * max(element.scaleStart, element.scaleEnd);
  vec2 from = vec2(ray.origin.x + t0 * ray.direction.x, ray.origin.y + t0 * ray.direction.y) -
    element.start;
  vec2 to = vec2(ray.origin.x + t1 * ray.direction.x, ray.origin.y + t1 * ray.direction.y) -
    element.start;
  float across0 = dot(from, element.right);
  float across1 = dot(to, element.right);
  float along0 = dot(from, element.axis);
  float along1 = dot(to, element.axis);
  float beside = (across0 > 0.0f) == (across1 > 0.0f) ? min(abs(across0), abs(across1)) : 0.0f;
  float before = min(-along0, -along1);
  float beyond = min(along0, along1) - element.span;
  return max(beside, max(before, beyond)) - reach;
}

// The first crossing after `after` and before best.t of the element's facets (straight
// and revolved about its ends), of the planes across its ends that are not revolved and
// through its axis beyond those that are (a profile not centred), and of the walls up
// from its cuts' openings, where the ray passes above the base.
ReliefPathEvent reliefPathElementEvents(
  ReliefPathEvent best, ReliefPathElement element, ReliefRay ray, float base, float after)
{
  bool aboveBase = min(ray.origin.z + after * ray.direction.z,
                     ray.origin.z + best.t * ray.direction.z) < base;
  ReliefPathSweep sweep = reliefPathSweepOf(element, ray, base);
  vec2 lastPoint = reliefPathLastPoint(element);
  vec2 previous = lastPoint;
  bool previousSide = reliefPathSide(sweep, previous);
  vec4 pair = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  for (int k = 0; k < RELIEF_PATH_PROFILE_POINTS && k < element.points; ++k)
  {
    pair = k % 2 == 0 ? RELIEF_PATH_TEXEL(element.profile + k / 2) : pair;
    vec2 point = reliefPathPairPoint(pair, k);
    bool side = reliefPathSide(sweep, point);
    if (side != previousSide)
    {
      best = reliefPathStraightCrossing(best, element, sweep, previous, point, after);
    }
    previous = point;
    previousSide = side;
  }
  float alongAfter = sweep.along0 + after * sweep.along1;
  float alongBest = sweep.along0 + best.t * sweep.along1;
  // each end the ray passes beyond, where the profile is revolved (not at an exact
  // join), facet by facet (on llvmpipe, which runs each branch whether taken or not, a
  // loop that no lane of the fragments run together needs costs one pass)
  previous = lastPoint;
  bool startNeeded = min(alongAfter, alongBest) < 0.0f && (element.rounded & 1) != 0;
  bool endNeeded = max(alongAfter, alongBest) > element.span && (element.rounded & 2) != 0;
  int firstEnd = startNeeded ? -1 : 1;
  int revolved = (startNeeded ? element.points : 0) + (endNeeded ? element.points : 0);
  for (int k = 0; k < 2 * RELIEF_PATH_PROFILE_POINTS && k < revolved; ++k)
  {
    int end = k < element.points ? firstEnd : 1;
    int i = k < element.points ? k : k - element.points;
    previous = i == 0 ? lastPoint : previous;
    pair = i % 2 == 0 ? RELIEF_PATH_TEXEL(element.profile + i / 2) : pair;
    vec2 point = reliefPathPairPoint(pair, i);
    best = reliefPathRevolvedEvents(best, element, ray, base, previous, point, after, end);
    previous = point;
  }
  // the plane across an end that is not revolved, where the element gives way to its
  // neighbour (its state changes there, on no facet)
  if (sweep.along1 != 0.0f)
  {
    float tStart = (element.rounded & 1) == 0 ? -sweep.along0 / sweep.along1 : -1e30f;
    float tEnd =
      (element.rounded & 2) == 0 ? (element.span - sweep.along0) / sweep.along1 : -1e30f;
    vec3 normal = vec3(element.axis.x, element.axis.y, 0.0f);
    best = reliefPathKeep(best, tStart, after, normal, element.material);
    best = reliefPathKeep(best, tEnd, after, normal, element.material);
  }
  // beyond a revolved end, within its reach, the plane through the element's axis, where
  // the two halves of the revolved profile meet: one that is not centred changes state
  // there, on no facet
  if (!element.centred && sweep.h1.x != 0.0f)
  {
    float tAxis = -sweep.h0.x / sweep.h1.x;
    float along = sweep.along0 + tAxis * sweep.along1;
    bool beyondStart = along < 0.0f && (element.rounded & 1) != 0;
    bool beyondEnd = along > element.span && (element.rounded & 2) != 0;
    float past = beyondStart ? -along : along - element.span;
    float reach = element.halfWidth * element.extent *
      (beyondStart ? element.scaleStart : element.scaleEnd);
    if ((beyondStart || beyondEnd) && past <= reach)
    {
      best = reliefPathKeep(
        best, tAxis, after, vec3(element.right.x, element.right.y, 0.0f), element.material);
    }
  }
  // (no pass where the ray stays below the base)
  int walls = aboveBase ? element.points : 0;
  previous = lastPoint;
  for (int k = 0; k < RELIEF_PATH_PROFILE_POINTS && k < walls; ++k)
  {
    pair = k % 2 == 0 ? RELIEF_PATH_TEXEL(element.profile + k / 2) : pair;
    vec2 point = reliefPathPairPoint(pair, k);
    if ((point.y > RELIEF_PATH_OPENING) != (previous.y > RELIEF_PATH_OPENING))
    {
      float opening = point.x +
        (RELIEF_PATH_OPENING - point.y) * (previous.x - point.x) / (previous.y - point.y);
      best = reliefPathWallEvents(best, element, ray, base, opening, after);
    }
    previous = point;
  }
  return best;
}

// Where the ray, within one cell from tFrom to tTo, first passes from air into matter
// (intoMatter) or from matter into air, with the normal and material of the surface
// crossed there; t = -1 where it does not. `nearest` counts the cell's elements' gaps
// along the ray up to there (where `tracking`: for the view ray's region sampling),
// `samples` the element tests.
struct ReliefPathTransition
{
  float t;
  vec3 normal;
  float material;
  ReliefPathNearest nearest;
  int samples;
};

ReliefPathTransition reliefPathCellTransition(ReliefRay ray, int list, int count, vec2 near,
  float base, float top, float tFrom, float tTo, bool intoMatter, bool tracking)
{
  // Each element's state is kept between crossings (what it makes of the ray: 0 nothing,
  // 1 matter, 2 a cut, reliefPathElementClass; -1 out of reach) with its next crossing,
  // so a crossing re-tests its own element only; the base plane changes the state of the
  // elements in reach whose profile both cuts and adds (above it a profile adds, below it
  // cuts).
  float next[RELIEF_PATH_CELL_CAPACITY];
  vec3 nextNormal[RELIEF_PATH_CELL_CAPACITY];
  int kind[RELIEF_PATH_CELL_CAPACITY];
  float priority[RELIEF_PATH_CELL_CAPACITY];
  bool mixes[RELIEF_PATH_CELL_CAPACITY];
  ReliefPathTransition result;
  result.t = -1.0f;
  result.normal = vec3(0.0f, 0.0f, 1.0f);
  result.material = -1.0f;
  result.nearest = reliefPathNoneNear();
  result.samples = count;
  float tBase = ray.direction.z != 0.0f ? (base - ray.origin.z) / ray.direction.z : -1e30f;
  // the ray's path up to the base, where most rays stop: its gaps are the ones that
  // count for a transition there (the footprint's rays differ only where the view ray's path
  // up to its transition passes near a feature)
  float tToBase = clamp(tBase, tFrom, tTo);
  ReliefPathNearest nearestToBase = reliefPathNoneNear();
  // where nothing listed rises above the base (the cell's top, its highest depth, lies at
  // or below it), a ray that descends is in air until it reaches the base: its crossings
  // count from there (no walls up from a cut's opening, none of the base plane)
  float tEvents = top >= base && ray.direction.z > 0.0f ? tToBase : tFrom;
  tBase = tBase > tEvents + 1e-6f && tBase < tTo ? tBase : tTo;
  int mixing = 0; // count where a listed element's profile both cuts and adds, else 0
  // no element reaches above the cell's top: a ray that descends meets them, and the
  // footprint's rays beside it (at the same depths) come near them, only from there
  float tBelowTop = ray.direction.z > 0.0f
    ? clamp((top - ray.origin.z) / ray.direction.z, tFrom, tTo) : tFrom;
  float t = tEvents;
  vec3 normal = vec3(0.0f, 0.0f, 1.0f);
  float material = -1.0f;
  bool atBase = false;
  int j = -1;
  // the highest addition that holds the ray where the cell's crossings start
  float startPriority = -1e30f;
  float startMaterial = -1.0f;
  for (int e = 0; e <= RELIEF_PATH_EVENTS; ++e)
  {
    // the elements' updates, in one loop of one element's update (on llvmpipe each block
    // of code costs a pass whether any fragment needs it or not): first every listed
    // element's reach, and where the ray comes within it, its first crossing and its state;
    // after a crossing, the crossed element's next crossing and state, or at the base
    // plane the state of every element in reach whose profile both cuts and adds (a cut's
    // state is the same on both sides of its opening; an addition ends on the base where
    // one of its facets lies, whose crossing tells its state)
    bool starting = e == 0;
    int updates = starting ? count : (atBase ? mixing : 1);
    for (int m = 0; m < RELIEF_PATH_CELL_CAPACITY && m < updates; ++m)
    {
      int k = starting || atBase ? m : j;
      int texel = reliefPathListed(list, k);
      ReliefPathElement element = reliefPathListedElement(list, texel, near);
      bool update = starting || !atBase || (kind[k] >= 0 && mixes[k]);
      if (starting)
      {
        priority[k] = element.priority;
        mixes[k] = reliefPathMixes(element);
        mixing = mixes[k] ? count : mixing;
        next[k] = tTo;
        nextNormal[k] = vec3(0.0f, 0.0f, 1.0f);
        kind[k] = -1;
        float gap = reliefPathGap(element, ray, tBelowTop, tTo);
        if (tracking)
        {
          result.nearest = reliefPathNearer(result.nearest, gap, texel, element.joins, near);
          nearestToBase = reliefPathNearer(nearestToBase,
            reliefPathGap(element, ray, tBelowTop, max(tToBase, tBelowTop)), texel,
            element.joins, near);
        }
        update = gap <= 0.0f;
      }
      if (update)
      {
        material = starting || atBase ? material : element.material;
        ReliefPathEvent following;
        following.t = atBase ? next[k] : tTo;
        following.normal = nextNormal[k];
        following.material = -1.0f;
        if (!atBase)
        {
          following = reliefPathElementEvents(following, element, ray, base, t + 1e-6f);
        }
        next[k] = following.t;
        nextNormal[k] = following.normal;
        kind[k] = reliefPathElementClass(
          element, reliefRayAt(ray, 0.5f * (t + min(following.t, tBase))), base);
        result.samples += starting ? 0 : 1;
        bool adds = starting && kind[k] == 1 && element.priority >= startPriority;
        startPriority = adds ? element.priority : startPriority;
        startMaterial = adds ? element.material : startMaterial;
      }
    }
    // the next crossing: the base (j = -1) or an element's
    float tNext = tBase;
    j = -1;
    for (int k = 0; k < RELIEF_PATH_CELL_CAPACITY && k < count; ++k)
    {
      j = next[k] < tNext ? k : j;
      tNext = min(tNext, next[k]);
    }
    // matter between t and tNext: the highest priority among the elements that hold the
    // ray there decides, a cut winning among equals; elsewhere the base surface. Crossings
    // closer than 1e-6 (elements that meet, facets that join) are taken as one.
    if (tNext > t + 1e-6f || tNext >= tTo)
    {
      float best = -1e30f;
      bool cut = false;
      bool held = false;
      for (int k = 0; k < RELIEF_PATH_CELL_CAPACITY && k < count; ++k)
      {
        if (kind[k] > 0 && priority[k] >= best)
        {
          cut = priority[k] > best ? kind[k] == 2 : (cut || kind[k] == 2);
          best = priority[k];
          held = true;
        }
      }
      bool matter = held ? !cut : ray.origin.z + 0.5f * (t + tNext) * ray.direction.z >= base;
      if (matter == intoMatter)
      {
        result.nearest = t <= tToBase ? nearestToBase : result.nearest;
        result.t = t;
        result.normal = normal;
        // (a ray that starts in an addition, on a top at the polygon: that addition's)
        result.material = e == 0 && held ? startMaterial : material;
        return result;
      }
    }
    if (tNext >= tTo)
    {
      return result;
    }
    t = tNext;
    atBase = j < 0;
    normal = atBase ? vec3(0.0f, 0.0f, 1.0f) : nextNormal[max(j, 0)];
    material = -1.0f;
    tBase = atBase ? tTo : tBase;
  }
  return result;
}

// A walk's hit at tHit (a miss at tEnd where tHit < 0), its normal facing back along the
// ray, out of the matter it enters; its clear point a little back along the ray, at most
// half way to tStart (a ray that rises there goes back deeper).
ReliefHit reliefPathHit(
  ReliefRay ray, float tStart, float tEnd, float tHit, vec3 normal, float material, int samples)
{
  float facing = dot(normal, ray.direction);
  reliefPathHitNormal = facing > 0.0f ? -normal : normal;
  reliefPathHitMaterial = material;
  bool found = tHit >= 0.0f;
  float t = found ? tHit : tEnd;
  float back = min(1e-3f / max(abs(ray.direction.z), 1e-6f), 0.5f * (t - tStart));
  return reliefHitAt(ray, t, found ? max(tStart, t - back) : t, found, samples);
}

// The deepest the ray gets from t0 to t1: its depth is linear in t, or quadratic below a
// curved frame's quadric (reliefQuadricFrame), deepest at its apex where that lies between.
float reliefPathDeepestOn(ReliefRay ray, float t0, float t1)
{
  float deepest = max(reliefRayAt(ray, t0).z, reliefRayAt(ray, t1).z);
  float apex = ray.bend < 0.0f ? -0.5f * ray.direction.z / ray.bend : t0;
  return apex > t0 && apex < t1 ? max(deepest, reliefRayAt(ray, apex).z) : deepest;
}

// How many straight pieces the ray is followed in from t0 to t1, each within 1/256 of
// depth of it (a quadratic strays from its chord by a quarter of its t^2 term times the
// square of the chord's span), at most RELIEF_PATH_PIECES; one for a straight ray.
#define RELIEF_PATH_PIECES 16
int reliefPathPieces(ReliefRay ray, float t0, float t1)
{
  return int(clamp(ceil((t1 - t0) * 8.0f * sqrt(abs(ray.bend))), 1.0f, float(RELIEF_PATH_PIECES)));
}

// The straight ray through the ray's points at t0 and t1: its chord; its tangent at t0
// where the two are one (a ray that starts on a cell's edge), so that a hit there still
// faces the ray.
ReliefRay reliefPathChord(ReliefRay ray, float t0, float t1)
{
  float depth0 = reliefRayAt(ray, t0).z;
  float depth1 = reliefRayAt(ray, t1).z;
  ReliefRay chord = ray;
  chord.direction.z =
    t1 > t0 ? (depth1 - depth0) / (t1 - t0) : ray.direction.z + 2.0f * ray.bend * t0;
  chord.origin.z = depth0 - chord.direction.z * t0;
  chord.bend = 0.0f;
  chord.exact = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  return chord;
}

#ifdef RELIEF_CURVED_FRAME
// The straight piece of a curved ray the last reliefPathCellEntry ended in, and where it
// starts: a hit lies on its facet along it (the curve strays up to 1/256 of depth from
// there), and the hit's clear point, where its shadow ray starts, in air before it on
// that piece.
ReliefRay reliefPathPiece;
float reliefPathPieceStart;
#endif

// Where the ray first enters matter in a cell from tIn to tOut (reliefPathCellTransition).
// Below a curved frame's quadric (RELIEF_CURVED_FRAME) the ray bends, and is followed in
// straight pieces (the paper tracks the surface's curvature along the ray, s5.1).
ReliefPathTransition reliefPathCellEntry(ReliefRay ray, int list, int count, vec2 near,
  float base, float top, float tIn, float tOut, bool tracking)
{
#ifdef RELIEF_CURVED_FRAME
  int pieces = reliefPathPieces(ray, tIn, tOut);
  ReliefPathTransition entry;
  ReliefPathNearest nearest = reliefPathNoneNear();
  int samples = 0;
  int p = 0;
  for (; p < RELIEF_PATH_PIECES && p < pieces; ++p)
  {
    float t0 = mix(tIn, tOut, float(p) / float(pieces));
    float t1 = mix(tIn, tOut, float(p + 1) / float(pieces));
    entry = reliefPathCellTransition(
      reliefPathChord(ray, t0, t1), list, count, near, base, top, t0, t1, true, tracking);
    samples += entry.samples;
    nearest = reliefPathNearer(
      nearest, entry.nearest.gap, entry.nearest.element, entry.nearest.joins, entry.nearest.near);
    nearest = reliefPathNearer(nearest, entry.nearest.second, -1, 0, near);
    if (entry.t >= 0.0f)
    {
      break;
    }
  }
  entry.nearest = nearest;
  entry.samples = samples;
  reliefPathPieceStart = mix(tIn, tOut, float(p) / float(pieces));
  reliefPathPiece =
    reliefPathChord(ray, reliefPathPieceStart, mix(tIn, tOut, float(p + 1) / float(pieces)));
  return entry;
#else
  // (a loop of one piece costs llvmpipe a tenth of the frame)
  return reliefPathCellTransition(ray, list, count, near, base, top, tIn, tOut, true, tracking);
#endif
}

// The path-feature walk of a ray from tStart to tEnd; the first entry into solid matter,
// or a miss at tEnd. `samples` counts cells visited and elements tested. Where `alone` is
// an element's data texel, through that element alone, its copy of the tile nearest to
// aloneNear, as one cell from tStart to tEnd: what region sampling's rays meet
// (reliefPathRegionSurfaces finds it in one pass; the unit tests compare the two). The
// nearest elements (reliefPathNearest) are tracked where `tracking` (a constant at each
// call: where false, the compiler leaves that code out of the walk).
ReliefHit reliefPathWalk(
  ReliefRay ray, float tStart, float tEnd, int alone, vec2 aloneNear, bool tracking)
{
  vec4 header = RELIEF_PATH_TEXEL(0);
  float base = header.x;
  vec2 size = vec2(header.z, header.w);
  ReliefGridRay grid;
  grid.origin = vec2(ray.origin.x * size.x, ray.origin.y * size.y);
  grid.direction = vec2(ray.direction.x * size.x, ray.direction.y * size.y);
  grid.depth = ray.origin.z;
  grid.descent = ray.direction.z;
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  vec2 ahead = vec2(max(signs.x, 0.0f), max(signs.y, 0.0f));
  vec2 cell = floor(reliefGridAt(grid, tStart));
  float tIn = tStart;
  int samples = 0;
  float tHit = -1.0f;
  vec3 normal = vec3(0.0f, 0.0f, 1.0f);
  float material = -1.0f;
  ReliefPathNearest nearest = reliefPathNoneNear();
  for (int i = 0; i < RELIEF_MAX_ITERATIONS && tHit < 0.0f; ++i)
  {
    // the cells the ray passes over above their highest feature (Algorithm 1), and those
    // that list nothing, where a straight ray that descends meets the base alone, in a
    // loop of their own (its steps counted with the walk's): on llvmpipe the fragments
    // run together test a cell's elements once all of them have come to such a cell
    vec2 next = vec2(0.0f, 0.0f);
    float tOut = tIn;
    vec4 cellTexel = vec4(0.0f, 0.0f, 0.0f, 0.0f);
    bool over = false;
    bool plain = false;
    for (; i < RELIEF_MAX_ITERATIONS; ++i)
    {
      next = reliefCrossings(grid, cell + ahead, signs, inverseRun);
      tOut = max(min(min(next.x, next.y), tEnd), tIn);
      cellTexel = alone > 0 ? vec4(float(-alone), 1.0f, -1e30f, 0.0f) : RELIEF_PATH_CELL(cell);
      tOut = alone > 0 ? tEnd : tOut;
      samples += alone > 0 ? 0 : 1;
      over = reliefPathDeepestOn(ray, tIn, tOut) < cellTexel.z;
      plain = cellTexel.y < 0.5f && ray.bend == 0.0f && ray.direction.z > 0.0f;
#ifdef RELIEF_CURVED_FRAME
      plain = false; // (a curved frame's hit lies on the piece its cell's entry keeps)
#endif
      float tBase = (base - ray.origin.z) / max(ray.direction.z, 1e-30f);
      tHit = plain && !over ? max(tIn, tBase) : tHit;
      if (!(over || plain) || tHit >= 0.0f || tOut >= tEnd)
      {
        break;
      }
      cell = reliefStepCell(cell, next, signs);
      tIn = tOut;
    }
    if (i >= RELIEF_MAX_ITERATIONS)
    {
      break; // out of steps: a miss
    }
    if (!(over || plain))
    {
      int count = min(int(cellTexel.y), RELIEF_PATH_CELL_CAPACITY);
      vec2 centre =
        alone > 0 ? aloneNear : vec2((cell.x + 0.5f) / size.x, (cell.y + 0.5f) / size.y);
      ReliefPathTransition entry =
        reliefPathCellEntry(ray, int(cellTexel.x), count, centre, base, cellTexel.z, tIn, tOut,
          tracking);
      samples += entry.samples;
      // the cell's second is another element than its nearest, and so counted exactly
      nearest = reliefPathNearer(nearest, entry.nearest.gap, entry.nearest.element,
        entry.nearest.joins, entry.nearest.near);
      nearest = reliefPathNearer(nearest, entry.nearest.second, -1, 0, centre);
      if (entry.t >= 0.0f)
      {
        tHit = entry.t;
        normal = entry.normal;
        material = entry.material;
      }
    }
    if (tHit >= 0.0f || tOut >= tEnd)
    {
      break;
    }
    cell = reliefStepCell(cell, next, signs);
    tIn = tOut;
  }
  reliefPathNearest = nearest;
#ifdef RELIEF_CURVED_FRAME
  ray = tHit >= 0.0f ? reliefPathPiece : ray;
  tStart = tHit >= 0.0f ? reliefPathPieceStart : tStart;
#endif
  return reliefPathHit(ray, tStart, tEnd, tHit, normal, material, samples);
}

// Where a straight ray reaches the deepest cut.
float reliefPathStraightEnd(ReliefRay ray)
{
  float deepest = RELIEF_PATH_TEXEL(0).y;
  return max((deepest - ray.origin.z) / max(ray.direction.z, 1e-12f) + 1e-4f, 1e-4f);
}

// The walk of a footprint's ray from depth 0 to the deepest cut (a curved frame's ray
// spans its range to there over t in [0, 1]: reliefQuadricFrame), through one element
// alone (its data texel; its copy of the tile nearest to `near`), on straight through its
// joins (reliefPathListedElement), or through all of them where `element` is 0; the
// nearest elements tracked where `tracking` (reliefPathWalk).
ReliefHit reliefPathElementWalk(ReliefRay ray, int element, vec2 near, bool tracking)
{
  return reliefPathWalk(
    ray, 0.0f, ray.bend != 0.0f ? 1.0f : reliefPathStraightEnd(ray), element, near, tracking);
}

// The path-feature search as a relief search: the view ray through all the features.
ReliefHit reliefSearchPathFeatures(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefPathElementWalk(ray, 0, vec2(0.0f, 0.0f), true);
}

// How far from its centre a pixel reaches in (u, v), whose neighbours along screen x and
// y lie alongX and alongY away: half its parallelogram's longer diagonal.
float reliefPathPixelReach(vec2 alongX, vec2 alongY)
{
  return 0.5f * max(length(alongX + alongY), length(alongX - alongY));
}

// Whether no feature but the nearest element and those its path goes on into comes
// within `reach` (the pixel's) of the view ray from t0 to t1 (in each cell, below the
// cell's top: none reaches above it): the stretch where the pixel's rays fall into that
// element and run on below the view ray's hit, which `nearest` did not judge. The
// features are those the cells there list (each extended by its reach); where that
// stretch passes more than 16 cells, false.
bool reliefPathAloneThere(ReliefPathNearest nearest, ReliefRay ray, float t0, float t1, float reach)
{
  vec4 header = RELIEF_PATH_TEXEL(0);
  vec2 size = vec2(header.z, header.w);
  vec2 from = reliefRayUV(ray, t0);
  vec2 to = reliefRayUV(ray, t1);
  vec2 first = floor((min(from, to) - vec2(reach, reach)) * size);
  vec2 last = floor((max(from, to) + vec2(reach, reach)) * size);
  int across = int(last.x - first.x) + 1;
  int cells = across * (int(last.y - first.y) + 1);
  if (cells > 16)
  {
    return false;
  }
  for (int c = 0; c < 16 && c < cells; ++c)
  {
    vec2 cell = first + vec2(float(c % across), float(c / across));
    vec4 cellTexel = RELIEF_PATH_CELL(cell);
    vec2 centre = vec2((cell.x + 0.5f) / size.x, (cell.y + 0.5f) / size.y);
    float from = max(t0, (cellTexel.z - ray.origin.z) / ray.direction.z);
    int count = from <= t1 ? min(int(cellTexel.y), RELIEF_PATH_CELL_CAPACITY) : 0;
    for (int k = 0; k < RELIEF_PATH_CELL_CAPACITY && k < count; ++k)
    {
      int texel = reliefPathListed(int(cellTexel.x), k);
      if (!reliefPathSameFeature(nearest, texel) &&
        reliefPathGap(reliefPathElement(texel, centre), ray, from, t1) <= reach)
      {
        return false;
      }
    }
  }
  return true;
}

// Region sampling (s5.7). Where a pixel's footprint meets one straight element alone, what
// each of its rays sees depends on one number: where the ray crosses the base, across the
// element. It changes only where a profile point, or a point where the profile meets the
// base, projects along the rays; between two such points one ray tells the surface, weighed
// by the share of the pixel there. Spread across the element, the pixel (tcoord per pixel
// along x and y, a parallelogram) is the sum of two boxes: a trapezoid. The regions are up
// to four offsets across (in (u, v), along `right`) with their weights, for the nearest
// element of the view ray's walk (reliefPathNearest), on straight through its joins; none
// where the rays pass an end of it that no element goes on from, or a joint where the
// path's outline strays more than an eighth of the pixel from straight, or cells that list
// other features, where the profile both cuts and adds (the wall up from its opening
// would change what is seen between those points) or where more than four.
struct ReliefPathRegions
{
  int count;
  vec4 offsets;
  vec4 weights;
  vec2 right;
  // what each region's ray meets (reliefPathRegionSurfaces): its outward normal, as
  // reliefPathHitNormal, by component, and its material, as reliefPathHitMaterial
  vec4 normalsU;
  vec4 normalsV;
  vec4 normalsDepth;
  vec4 materials;
};

ReliefPathRegions reliefPathNoRegions()
{
  ReliefPathRegions regions;
  regions.count = 0;
  regions.offsets = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  regions.weights = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  regions.right = vec2(0.0f, 0.0f);
  regions.normalsU = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  regions.normalsV = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  regions.normalsDepth = vec4(-1.0f, -1.0f, -1.0f, -1.0f);
  regions.materials = vec4(-1.0f, -1.0f, -1.0f, -1.0f);
  return regions;
}

// Which side of the sweep's line each region's ray sees the profile point p on
// (reliefPathSide, the line's x being the same for all of them).
bvec4 reliefPathRegionSides(float lineX, vec4 lineY, vec4 lineZ, vec2 p)
{
  return greaterThan(vec4(lineX * p.x, lineX * p.x, lineX * p.x, lineX * p.x) + lineY * p.y +
      lineZ, vec4(0.0f, 0.0f, 0.0f, 0.0f));
}

// What the regions' rays meet: each ray, at its region's offset across the element, through
// the element alone, beside its straight part (where the regions hold) and across a profile
// that only cuts or only adds (reliefPathRegions refuses one that does both). A cut's ray that
// reaches the base within the cut's opening goes on in air to the first facet after it
// (where it leaves the profile's inside; the facet that closes the profile at the base is
// passed, as the walk starts a cut's crossings just after the base); an addition's ray
// meets the first facet it crosses above the base (one that tops out at depth 0, where the
// ray starts); any other meets the base. That is what their walks find
// (reliefPathElementWalk; the unit tests compare the two), in one pass over the profile for
// the four rays together: on llvmpipe each walk costs a pass of the whole walk's code.
ReliefPathRegions reliefPathRegionSurfaces(
  ReliefPathRegions regions, ReliefPathElement element, ReliefRay ray, float base)
{
  ReliefPathSweep sweep = reliefPathSweepOf(element, ray, base);
  // a region's ray starts offset along `right`: its h0.x moves by offset / half width
  vec4 h0x = vec4(sweep.h0.x, sweep.h0.x, sweep.h0.x, sweep.h0.x) +
    regions.offsets / element.halfWidth;
  vec4 h0y = vec4(sweep.h0.y, sweep.h0.y, sweep.h0.y, sweep.h0.y);
  vec4 h0z = vec4(sweep.h0.z, sweep.h0.z, sweep.h0.z, sweep.h0.z);
  vec4 none = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  vec4 unmet = vec4(1e30f, 1e30f, 1e30f, 1e30f);
  float tBase = (base - ray.origin.z) / ray.direction.z;
  vec4 baseT = vec4(tBase, tBase, tBase, tBase);
  float scaleAtBase = sweep.h0.z + tBase * sweep.h1.z;
  vec4 xAtBase = (h0x + baseT * sweep.h1.x) / max(scaleAtBase, 1e-6f);
  bool cut = element.top >= 0.0f;
  float lineX = sweep.h0.y * sweep.h1.z - sweep.h0.z * sweep.h1.y;
  vec4 lineY = h0z * sweep.h1.x - h0x * sweep.h1.z;
  vec4 lineZ = h0x * sweep.h1.y - h0y * sweep.h1.x;
  vec4 openings = none; // the profile's edges right of the base point, just below the base
  vec4 first = unmet;
  vec4 facetX = none;
  vec4 facetY = none;
  vec4 facetZ = none;
  vec2 previous = reliefPathLastPoint(element);
  bvec4 previousSide = reliefPathRegionSides(lineX, lineY, lineZ, previous);
  vec4 pair = none;
  for (int k = 0; k < RELIEF_PATH_PROFILE_POINTS && k < element.points; ++k)
  {
    pair = k % 2 == 0 ? RELIEF_PATH_TEXEL(element.profile + k / 2) : pair;
    vec2 point = reliefPathPairPoint(pair, k);
    if ((point.y > RELIEF_PATH_OPENING) != (previous.y > RELIEF_PATH_OPENING))
    {
      float x = point.x +
        (RELIEF_PATH_OPENING - point.y) * (previous.x - point.x) / (previous.y - point.y);
      openings += vec4(lessThan(xAtBase, vec4(x, x, x, x)));
    }
    // the facet's crossing for each ray whose line the facet's ends straddle
    // (reliefPathStraightCrossing)
    bvec4 side = reliefPathRegionSides(lineX, lineY, lineZ, point);
    vec3 facet = cross(vec3(previous.x, previous.y, 1.0f), vec3(point.x, point.y, 1.0f));
    float rate = dot(facet, sweep.h1);
    vec4 t = -(facet.x * h0x + facet.y * h0y + facet.z * h0z) / (rate != 0.0f ? rate : 1.0f);
    vec4 along = vec4(sweep.along0, sweep.along0, sweep.along0, sweep.along0) + t * sweep.along1;
    vec4 kept = vec4(notEqual(side, previousSide)) * vec4(lessThan(t, first)) *
      vec4(greaterThanEqual(along, none)) * vec4(lessThanEqual(along, element.span + none)) *
      vec4(greaterThan(h0z + t * sweep.h1.z, none)) *
      (cut ? vec4(greaterThan(t, baseT + 1e-6f)) :
             vec4(greaterThan(t, none - 1e-6f)) * vec4(lessThan(t, baseT)));
    bvec4 keep = greaterThan(kept, vec4(0.5f, 0.5f, 0.5f, 0.5f));
    keep = rate != 0.0f ? keep : bvec4(false, false, false, false);
    first = mix(first, t, keep);
    facetX = mix(facetX, vec4(facet.x, facet.x, facet.x, facet.x), keep);
    facetY = mix(facetY, vec4(facet.y, facet.y, facet.y, facet.y), keep);
    facetZ = mix(facetZ, vec4(facet.z, facet.z, facet.z, facet.z), keep);
    previous = point;
    previousSide = side;
  }
  // a cut's ray meets a facet where it reached the base inside the opening (an odd count of
  // edges right of it) where the element is there at all
  vec4 inOpening = scaleAtBase > 1e-6f ? mod(openings, vec4(2.0f, 2.0f, 2.0f, 2.0f)) : none;
  bvec4 met = lessThan(first, unmet);
  bvec4 onFacet =
    cut ? greaterThan(inOpening * vec4(met), vec4(0.5f, 0.5f, 0.5f, 0.5f)) : met;
  // the facet's normal as reliefPathStraightCrossing gives it, facing back along the ray
  float slope = sweep.slope;
  vec4 u = facetX * (element.right.x / element.halfWidth) + facetZ * (slope * element.axis.x);
  vec4 v = facetX * (element.right.y / element.halfWidth) + facetZ * (slope * element.axis.y);
  u = mix(none, u, onFacet);
  v = mix(none, v, onFacet);
  vec4 depth = mix(vec4(1.0f, 1.0f, 1.0f, 1.0f), facetY, onFacet);
  vec4 facing = u * ray.direction.x + v * ray.direction.y + depth * ray.direction.z;
  vec4 flip = mix(vec4(1.0f, 1.0f, 1.0f, 1.0f), vec4(-1.0f, -1.0f, -1.0f, -1.0f),
    greaterThan(facing, none));
  regions.normalsU = flip * u;
  regions.normalsV = flip * v;
  regions.normalsDepth = flip * depth;
  regions.materials = mix(vec4(-1.0f, -1.0f, -1.0f, -1.0f),
    vec4(element.material, element.material, element.material, element.material), onFacet);
  return regions;
}

// The share of a sum of two centred boxes, of widths a and b, below s.
float reliefPathBoxesBelow(float s, float a, float b)
{
  float wide = max(a, b);
  if (!(wide > 1e-12f))
  {
    return s >= 0.0f ? 1.0f : 0.0f;
  }
  float narrow = max(min(a, b), 1e-3f * wide);
  float outer = 0.5f * (wide + narrow);
  float inner = 0.5f * (wide - narrow);
  float r0 = max(s + outer, 0.0f);
  float r1 = max(s + inner, 0.0f);
  float r2 = max(s - inner, 0.0f);
  float r3 = max(s - outer, 0.0f);
  return clamp((r0 * r0 - r1 * r1 - r2 * r2 + r3 * r3) / (2.0f * wide * narrow), 0.0f, 1.0f);
}

ReliefPathRegions reliefPathRegions(
  ReliefRay ray, ReliefPathNearest nearest, vec2 alongX, vec2 alongY)
{
  ReliefPathRegions regions = reliefPathNoRegions();
  if (!(ray.direction.z > 1e-6f) || ray.bend != 0.0f)
  {
    return regions; // the regions' rays are straight
  }
  float base = RELIEF_PATH_TEXEL(0).x;
  vec3 atBase = reliefRayAt(ray, (base - ray.origin.z) / ray.direction.z);
  ReliefPathElement element =
    reliefPathListedElement(-nearest.element, nearest.element, nearest.near);
  regions.right = element.right;
  // the view ray's base crossing, and how its rays move across and along per depth
  vec2 fromStart = vec2(atBase.x, atBase.y) - element.start;
  float across = dot(fromStart, element.right);
  float along = dot(fromStart, element.axis);
  vec2 direction = vec2(ray.direction.x, ray.direction.y);
  float slantAcross = dot(direction, element.right) / ray.direction.z;
  float slantAlong = dot(direction, element.axis) / ray.direction.z;
  float widthX = abs(dot(alongX, element.right));
  float widthY = abs(dot(alongY, element.right));
  float halfAcross = 0.5f * (widthX + widthY);
  float halfAlong = 0.5f * (abs(dot(alongX, element.axis)) + abs(dot(alongY, element.axis)));
  // beside the straight part wherever the rays come within reach, from the element's
  // highest point down
  float largest = max(element.scaleStart, element.scaleEnd);
  float reach = element.halfWidth * element.extent * largest + halfAcross;
  float top = max(ray.origin.z,
    base + min(element.top * element.scaleStart, element.top * element.scaleEnd));
  float bottom = base + max(element.bottom, 0.0f) * largest;
  if (abs(slantAcross) > 1e-9f)
  {
    float d0 = base + (-reach - across) / slantAcross;
    float d1 = base + (reach - across) / slantAcross;
    top = max(top, min(d0, d1));
    bottom = min(bottom, max(d0, d1));
  }
  else if (abs(across) > reach)
  {
    bottom = top - 1.0f;
  }
  if (top <= bottom)
  {
    float along0 = along + (top - base) * slantAlong;
    float along1 = along + (bottom - base) * slantAlong;
    float first = min(along0, along1) - halfAlong;
    float last = max(along0, along1) + halfAlong;
    // how far the path strays past its joints from the straight element, to the rays
    float halfExtent = element.halfWidth * element.extent * largest;
    bool before = (element.joins & 1) != 0;
    bool after = (element.joins & 2) != 0;
    float startJoint = before ? reliefPathSpan(nearest.element - 2) : 0.0f;
    float endJoint = startJoint + reliefPathSpan(nearest.element);
    float strayBefore =
      before ? reliefPathStray(nearest.element - 2, startJoint - first, halfExtent) : 0.0f;
    float strayAfter =
      after ? reliefPathStray(nearest.element, last - endJoint, halfExtent) : 0.0f;
    if (first < 0.0f || last > element.span ||
      max(strayBefore, strayAfter) > 0.25f * halfAcross)
    {
      return regions;
    }
  }
  if (reliefPathMixes(element))
  {
    return regions;
  }
  // where the rays come within the element's reach, no other feature (beside it they
  // meet the base, as the view ray did)
  if (top <= bottom &&
    !reliefPathAloneThere(nearest, ray, (top - ray.origin.z) / ray.direction.z,
      (bottom - ray.origin.z) / ray.direction.z, reliefPathPixelReach(alongX, alongY)))
  {
    return regions;
  }
  // the points where what the rays see changes, within the footprint, in order
  float scale = mix(element.scaleStart, element.scaleEnd, clamp(along / element.span, 0.0f, 1.0f));
  float breaks[3];
  int breakCount = 0;
  vec2 previous = reliefPathLastPoint(element);
  vec4 pair = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  for (int k = 0; k < RELIEF_PATH_PROFILE_POINTS && k < element.points && breakCount <= 3; ++k)
  {
    pair = k % 2 == 0 ? RELIEF_PATH_TEXEL(element.profile + k / 2) : pair;
    vec2 point = reliefPathPairPoint(pair, k);
    // the point, and where the segment to it crosses the base
    bool crosses = point.y != 0.0f && previous.y != 0.0f && (point.y > 0.0f) != (previous.y > 0.0f);
    float meets = crosses ? point.x - point.y * (previous.x - point.x) / (previous.y - point.y) : 0.0f;
    for (int m = 0; m < 2 && (m == 0 || crosses); ++m)
    {
      float at = m == 0 ? scale * (element.halfWidth * point.x - point.y * slantAcross) - across
                        : scale * element.halfWidth * meets - across;
      bool known = false;
      for (int j = 0; j < 3 && j < breakCount; ++j)
      {
        known = known || abs(breaks[j] - at) <= 1e-6f * halfAcross;
      }
      if (abs(at) < halfAcross && !known)
      {
        // kept in order; a fourth ends region sampling
        int slot = breakCount;
        for (int j = 2; j >= 0; --j)
        {
          if (j < breakCount && breakCount < 3 && breaks[j] > at)
          {
            breaks[j + 1] = breaks[j];
            slot = j;
          }
        }
        if (slot < 3)
        {
          breaks[slot] = at;
        }
        breakCount += 1;
      }
    }
    previous = point;
  }
  if (breakCount > 3)
  {
    return regions;
  }
  float low = -halfAcross;
  float below = 0.0f;
  for (int r = 0; r <= breakCount; ++r)
  {
    float high = r < breakCount ? breaks[r] : halfAcross;
    float share = r < breakCount ? reliefPathBoxesBelow(high, widthX, widthY) : 1.0f;
    float middle = 0.5f * (low + high);
    float weight = share - below;
    regions.offsets.x = r == 0 ? middle : regions.offsets.x;
    regions.offsets.y = r == 1 ? middle : regions.offsets.y;
    regions.offsets.z = r == 2 ? middle : regions.offsets.z;
    regions.offsets.w = r == 3 ? middle : regions.offsets.w;
    regions.weights.x = r == 0 ? weight : regions.weights.x;
    regions.weights.y = r == 1 ? weight : regions.weights.y;
    regions.weights.z = r == 2 ? weight : regions.weights.z;
    regions.weights.w = r == 3 ? weight : regions.weights.w;
    low = high;
    below = share;
  }
  regions.count = breakCount + 1;
  return reliefPathRegionSurfaces(regions, element, ray, base);
}

// Self-shadowing (s5.6): the same walk along the light ray, from where it enters the
// features (depth 0) to the hit's clear point; meeting matter on the way blocks the light.
float reliefPathLightVisibility(vec3 clearPoint, vec3 lightDirection)
{
  if (lightDirection.z >= 0.0f)
  {
    return 0.0f;
  }
  if (clearPoint.z <= 0.0f)
  {
    return 1.0f;
  }
  vec3 hitNormal = reliefPathHitNormal;
  float hitMaterial = reliefPathHitMaterial;
  ReliefPathNearest hitNearest = reliefPathNearest;
  ReliefHit blocked =
    reliefPathWalk(reliefLightRay(clearPoint, lightDirection), 0.0f, 1.0f, 0, vec2(0.0f, 0.0f),
      false);
  reliefPathHitNormal = hitNormal;
  reliefPathHitMaterial = hitMaterial;
  reliefPathNearest = hitNearest;
  return blocked.hit && blocked.t < 1.0f ? 0.0f : 1.0f;
}
