// vtkRelief: the impostor frame (Baboud and Decoret 2006, s4), for
// vtkOpenGLReliefImpostorMapper: a view ray through an object's box, mapped into each of
// vtkReliefImpostorFilter's views by that view's projective matrix (orthographic or
// reverse perspective: straight lines stay straight, s4), and the first point of the ray
// that every view's field holds inside the object. Written in the GLSL subset GLM also
// compiles (see vtkReliefCommon.glsl); the unit tests run it on the CPU.
//
// A view's field says which points may belong to the object: those on or behind the
// first surface its rays meet (depth >= field). Each view's set holds the whole object,
// so the object lies in their intersection, and the six views of a box carve it from six
// sides, as a visual hull does: a shape that every line along an axis meets in one
// stretch is held exactly. The first point of the intersection is found by searching
// views in turn: a view whose set does not hold the current point is searched from there
// with the mapper's method, which moves the point on to where that view's set begins;
// once every view holds the point, it is the hit. (s4.2 lets the nearest of six hits
// win, which fits fields that each cover a sixth of the box; fields that span the whole
// box, as the filter's do, hold far more than the object behind their surfaces, and only
// their intersection draws it.)
//
// The includer defines RELIEF_IMPOSTOR_VIEWS (1 or 6), RELIEF_IMPOSTOR_PROJECTION(view)
// (the view's mat4, model coordinates to (u w, v w, depth w, w)),
// RELIEF_IMPOSTOR_SELECT(view), which makes RELIEF_DEPTH, RELIEF_CELL_DEPTHS and the
// search's acceleration reads read that view's field, and
// RELIEF_IMPOSTOR_DEPTH_RATIO(view), the box's depth along the view over the size of its
// face, which makes the fields' slopes comparable between views.

// How far inside each face of the box the rays are clipped, as a share of its side: a
// field's empty columns hold depth 1, which a ray along its far face would otherwise
// touch. The filter pads the box by far more, so no surface lies that close to a face.
#define RELIEF_IMPOSTOR_INSET 1e-4f

// A point counts as inside a view's field within this depth, two steps of the 16-bit
// depths: the search's root and the test of the point may round apart, and a sheet of no
// thickness is stored rounded to the nearest step by each of two opposite views, which
// may then leave a step between them, holding nothing.
#define RELIEF_IMPOSTOR_DEPTH_TOLERANCE 3.1e-5f

// Searches of one ray, at most: each moves the point on, and views that agree need none.
#define RELIEF_IMPOSTOR_MAX_SEARCHES 24

// Where a ray crosses the box, in model coordinates.
struct ReliefImpostorSegment
{
  vec3 entry;
  vec3 exit;
  bool crosses;
};

// The part of the ray origin + s direction, s >= start, inside the box [low, high] shrunk
// by RELIEF_IMPOSTOR_INSET of its sides.
ReliefImpostorSegment reliefImpostorClip(
  vec3 origin, vec3 direction, vec3 low, vec3 high, float start)
{
  float enter = start;
  float leave = 1e30f;
  bool crosses = true;
  for (int axis = 0; axis < 3; ++axis)
  {
    float inset = RELIEF_IMPOSTOR_INSET * (high[axis] - low[axis]);
    float lowSide = low[axis] + inset;
    float highSide = high[axis] - inset;
    if (abs(direction[axis]) < 1e-30f)
    {
      crosses = crosses && origin[axis] >= lowSide && origin[axis] <= highSide;
    }
    else
    {
      float first = (lowSide - origin[axis]) / direction[axis];
      float second = (highSide - origin[axis]) / direction[axis];
      enter = max(enter, min(first, second));
      leave = min(leave, max(first, second));
    }
  }
  ReliefImpostorSegment segment;
  segment.crosses = crosses && enter < leave;
  segment.entry = origin + direction * enter;
  segment.exit = origin + direction * leave;
  return segment;
}

// A segment in one view: its ends in homogeneous view coordinates (u w, v w, depth w, w).
// Between them the view's (u, v, depth) run along a straight line, but not evenly: the
// point a share `share` along the segment in model space lies at parameter
// reliefImpostorViewParameter on the line (the same for orthographic views, w constant).
struct ReliefImpostorView
{
  vec4 entry;
  vec4 exit;
};

ReliefImpostorView reliefImpostorView(int view, ReliefImpostorSegment segment)
{
  ReliefImpostorView mapped;
  mapped.entry = RELIEF_IMPOSTOR_PROJECTION(view) * vec4(segment.entry, 1.0f);
  mapped.exit = RELIEF_IMPOSTOR_PROJECTION(view) * vec4(segment.exit, 1.0f);
  return mapped;
}

vec3 reliefImpostorProjected(vec4 point)
{
  return vec3(point.x / point.w, point.y / point.w, point.z / point.w);
}

// The line parameter of the point `share` of the way along the segment, and back.
float reliefImpostorViewParameter(ReliefImpostorView view, float share)
{
  return share * view.exit.w / ((1.0f - share) * view.entry.w + share * view.exit.w);
}

float reliefImpostorShare(ReliefImpostorView view, float parameter)
{
  return parameter * view.entry.w / ((1.0f - parameter) * view.exit.w + parameter * view.entry.w);
}

// The view's (u, v, depth) of the point `share` of the way along the segment.
vec3 reliefImpostorPointAt(ReliefImpostorView view, float share)
{
  return reliefImpostorProjected(mix(view.entry, view.exit, share));
}

// The selected view's field at `point` (u, v, depth): the depth of the bilinear patch the
// exact searches intersect (reliefCellGap's polynomial) and its gradient in (u, v).
vec3 reliefImpostorField(vec3 point)
{
  vec2 size = RELIEF_DEPTH_SIZE;
  vec2 at = vec2(point.x * size.x - 0.5f, point.y * size.y - 0.5f);
  vec2 cell = floor(at);
  vec4 depths = RELIEF_CELL_DEPTHS(cell);
  float x = at.x - cell.x;
  float y = at.y - cell.y;
  return vec3(mix(mix(depths.x, depths.y, x), mix(depths.z, depths.w, x), y),
    mix(depths.y - depths.x, depths.w - depths.z, y) * size.x,
    mix(depths.z - depths.x, depths.w - depths.y, x) * size.y);
}

// Whether the selected view's field holds `point`: on or behind its surface.
bool reliefImpostorHolds(vec3 point)
{
  return point.z >= reliefImpostorField(point).x - RELIEF_IMPOSTOR_DEPTH_TOLERANCE;
}

struct ReliefImpostorHit
{
  float share;  // how far along the segment, 0 at its entry, 1 at its exit
  int view;     // the view whose search placed the hit (0 for a hit at the entry)
  bool hit;     // false: the ray leaves the box outside the object
  int samples;  // height samples, the searches' and the tests'
};

// The first point of the segment inside every view's set (see the top of this file),
// each view searched by the mapper's method (RELIEF_SEARCH) from where the last search
// left the point.
ReliefImpostorHit reliefImpostorSearch(
  ReliefImpostorSegment segment, int linearSteps, int refinementSteps)
{
  ReliefImpostorHit result;
  result.share = 0.0f;
  result.view = -1;
  result.hit = false;
  result.samples = 0;
  for (int search = 0; search < RELIEF_IMPOSTOR_MAX_SEARCHES; ++search)
  {
    // the first view that does not hold the point, but the one that just placed it
    int outside = -1;
    for (int view = 0; view < RELIEF_IMPOSTOR_VIEWS; ++view)
    {
      if (outside < 0 && view != result.view)
      {
        RELIEF_IMPOSTOR_SELECT(view);
        result.samples += 1;
        if (!reliefImpostorHolds(reliefImpostorPointAt(reliefImpostorView(view, segment),
              result.share)))
        {
          outside = view;
        }
      }
    }
    if (outside < 0)
    {
      // every view holds the point: the hit; at the segment's start only where the near
      // plane cuts into the object, which shows its cut there
      result.hit = true;
      result.view = max(result.view, 0);
      break;
    }
    // that view's field searched along the rest of the segment
    RELIEF_IMPOSTOR_SELECT(outside);
    ReliefImpostorView view = reliefImpostorView(outside, segment);
    float from = reliefImpostorViewParameter(view, result.share);
    ReliefRay ray;
    ray.origin = reliefImpostorPointAt(view, result.share);
    ray.direction = reliefImpostorProjected(view.exit) - ray.origin;
    ray.bend = 0.0f;
    ray.exact = vec4(0.0f, 0.0f, 0.0f, 0.0f);
    ray.screenRun = RELIEF_UNKNOWN_RUN;
    ReliefHit found = RELIEF_SEARCH(ray, linearSteps, refinementSteps);
    result.samples += found.samples;
    if (!found.hit)
    {
      break;
    }
    float parameter = from + found.t * (1.0f - from);
    result.share = max(result.share, reliefImpostorShare(view, parameter));
    result.view = outside;
  }
  return result;
}

// The view to colour and light the hit from: of the views whose surface the hit lies on
// (within two depth texels of it), the one that sees that surface most squarely, where its
// field is least steep, and nearest the hit, in texels, which parts views that see two
// faces at an edge: a lid's point a texel from its rim lies a texel behind the wall a side
// view sees there, flat too, and on the lid the view from above sees. The view whose
// search placed the hit need not be it: along an edge, a side view's field slants between
// its texel rows (the bilinear field's skirt) and may place the hit on the top face, where
// the side view's textures hold the side.
int reliefImpostorShadingView(ReliefImpostorSegment segment, ReliefImpostorHit hit)
{
  int chosen = hit.view;
  float best = 1e30f;
  for (int view = 0; view < RELIEF_IMPOSTOR_VIEWS; ++view)
  {
    RELIEF_IMPOSTOR_SELECT(view);
    vec3 point = reliefImpostorPointAt(reliefImpostorView(view, segment), hit.share);
    vec3 field = reliefImpostorField(point);
    vec2 size = RELIEF_DEPTH_SIZE;
    float ratio = RELIEF_IMPOSTOR_DEPTH_RATIO(view);
    float slope = ratio * length(vec2(field.y, field.z));
    float texelsAway = abs(point.z - field.x) * ratio * max(size.x, size.y);
    if (point.z - field.x <= 2.0f / max(size.x, size.y) && field.x < 1.0f &&
      slope + texelsAway < best)
    {
      chosen = view;
      best = slope + texelsAway;
    }
  }
  return chosen;
}
