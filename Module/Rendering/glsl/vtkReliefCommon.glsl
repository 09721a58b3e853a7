// vtkRelief: types and helpers shared by every frame and every search method.
//
// Written in the subset of GLSL that GLM also compiles: the unit tests include this
// very file as C++, so the CPU mirror cannot drift from the shader. Rules: float
// literals carry an f suffix, no swizzles, no inout, structs returned by value.
// Height reads go through macros the includer defines: RELIEF_DEPTH(uv), the filtered
// depth; RELIEF_DEPTH_SIZE, texels per tile (vec2); RELIEF_CELL_DEPTHS(cell), the four
// stored depths at the corners of a cell (vec4: (i, j), (i+1, j), (i, j+1), (i+1, j+1)),
// cell indices unwrapped (the includer repeats them); RELIEF_DEPTH_REPEATS, true where
// the field repeats (GL_REPEAT), false where it is clamped at its edges.
//
// Relief texture space: (u, v, depth); u, v per tile (repeating), depth in [0, 1],
// 0 at the polygon, 1 deepest. A ray is a segment in that space, t in [0, 1].

struct ReliefRay
{
  vec3 origin;    // (u, v, depth) at t = 0
  vec3 direction; // change of (u, v, depth) from t = 0 to t = 1
  float bend;     // depth's t^2 term: 0 for a straight ray; below a curved surface's
                  // quadric the depth of a straight view ray is quadratic
                  // (vtkReliefQuadricFrame.glsl)
  vec4 exact;     // the exact distance's terms (vtkReliefQuadricFrame.glsl); w = 0: not used
  float screenRun; // how far its (u, v) move from t = 0 to 1 on screen, in units of the
                   // screen tolerance (reliefScreenRun): the Automatic search's budget;
                   // RELIEF_UNKNOWN_RUN where not known, which asks for an exact search
};

#define RELIEF_UNKNOWN_RUN 1e30f

struct ReliefHit
{
  vec3 position; // (u, v, depth) of the first intersection
  float t;       // its ray parameter
  vec3 clear;    // the last ray point the search found above the field (or the start)
  bool hit;      // false when the ray leaves the search range without meeting the field
  int samples;   // height samples the search took
};

#ifdef RELIEF_EXACT_DISTANCE
float reliefExactDepth(ReliefRay ray, float t, float verticalDepth);
#endif

vec3 reliefRayAt(ReliefRay ray, float t)
{
  float depth = ray.origin.z + t * (ray.direction.z + t * ray.bend);
#ifdef RELIEF_EXACT_DISTANCE
  depth = reliefExactDepth(ray, t, depth);
#endif
  return vec3(ray.origin.x + t * ray.direction.x, ray.origin.y + t * ray.direction.y, depth);
}

vec2 reliefRayUV(ReliefRay ray, float t)
{
  return vec2(ray.origin.x + t * ray.direction.x, ray.origin.y + t * ray.direction.y);
}

// True where the ray point lies on or below the height field.
bool reliefBelowField(vec3 point)
{
  return point.z >= RELIEF_DEPTH(vec2(point.x, point.y));
}

// The view ray of a fragment: it enters the relief at the polygon (depth 0, the
// fragment's texture coordinates) and is followed down to depth 1. direction is the
// view direction in texture-space units (du, dv, ddepth), ddepth > 0 going in; a
// grazing ray is clamped so its texture-space run stays finite.
ReliefRay reliefViewRay(vec2 entryUV, vec3 direction)
{
  float descent = max(direction.z, 1e-3f * length(vec2(direction.x, direction.y)));
  descent = max(descent, 1e-12f);
  ReliefRay ray;
  ray.origin = vec3(entryUV.x, entryUV.y, 0.0f);
  ray.direction = vec3(direction.x / descent, direction.y / descent, 1.0f);
  ray.bend = 0.0f;
  ray.exact = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  ray.screenRun = RELIEF_UNKNOWN_RUN;
  return ray;
}

// The screen distance, in units of `tolerance` pixels, that a move of `run` in (u, v)
// spans where moving one pixel along screen x changes (u, v) by alongX and along y by
// alongY (the entry's derivatives): the pixel offset p solving alongX p.x + alongY p.y =
// run. RELIEF_UNKNOWN_RUN where the derivatives hold no mapping or tolerance is 0.
float reliefScreenRun(vec2 run, vec2 alongX, vec2 alongY, float tolerance)
{
  float determinant = alongX.x * alongY.y - alongX.y * alongY.x;
  float scale = max(dot(alongX, alongX), dot(alongY, alongY));
  // a determinant within float cancellation of zero holds no mapping
  if (!(tolerance > 0.0f) || !(abs(determinant) > 1e-6f * scale))
  {
    return RELIEF_UNKNOWN_RUN;
  }
  vec2 pixels = vec2(alongY.y * run.x - alongY.x * run.y, alongX.x * run.y - alongX.y * run.x);
  float tolerances = length(pixels) / (abs(determinant) * tolerance);
  bool usable = tolerances >= 0.0f && tolerances < RELIEF_UNKNOWN_RUN; // not NaN
  return usable ? tolerances : RELIEF_UNKNOWN_RUN;
}

// The light ray of a hit: from where the ray toward the light leaves the relief
// (depth 0) down to the hit, so the same searches answer "what does the light meet
// first". lightDirection points from the hit toward the light in texture-space units
// (ddepth < 0 when the light is above the surface).
ReliefRay reliefLightRay(vec3 hitPosition, vec3 lightDirection)
{
  float ascent = max(-lightDirection.z, 1e-3f * length(vec2(lightDirection.x, lightDirection.y)));
  ascent = max(ascent, 1e-12f);
  float run = hitPosition.z / ascent;
  ReliefRay ray;
  ray.origin = vec3(hitPosition.x + lightDirection.x * run, hitPosition.y + lightDirection.y * run, 0.0f);
  ray.direction = hitPosition - ray.origin;
  ray.bend = 0.0f;
  ray.exact = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  ray.screenRun = RELIEF_UNKNOWN_RUN;
  return ray;
}

// A ray in texel coordinates, where texel (i, j)'s centre lies at (i, j): the cell
// floor(x) is the bilinear patch between four texel centres (Baboud and Decoret 2006, s3.1).
struct ReliefGridRay
{
  vec2 origin;    // texel coordinates at t = 0 (in the first tile on a repeating field)
  vec2 direction; // change of texel coordinates per unit t
  float depth;    // depth at t = 0
  float descent;  // change of depth per unit t, > 0
};

// On a repeating field the origin is moved into the first tile: a search's cells and
// crossings must agree to far less than a texel, and float texel coordinates far out in
// the tiling do not (an eighth of a texel apart 1000 tiles of 2048 texels out, where the
// exact searches' hits came out up to hundreds of texels off the field's).
ReliefGridRay reliefGridRay(ReliefRay ray, vec2 size)
{
  vec2 tile = RELIEF_DEPTH_REPEATS ? vec2(floor(ray.origin.x), floor(ray.origin.y))
                                   : vec2(0.0f, 0.0f);
  ReliefGridRay grid;
  grid.origin =
    vec2((ray.origin.x - tile.x) * size.x - 0.5f, (ray.origin.y - tile.y) * size.y - 0.5f);
  grid.direction = vec2(ray.direction.x * size.x, ray.direction.y * size.y);
  grid.depth = ray.origin.z;
  grid.descent = ray.direction.z;
  return grid;
}

vec2 reliefGridAt(ReliefGridRay grid, float t)
{
  return vec2(grid.origin.x + t * grid.direction.x, grid.origin.y + t * grid.direction.y);
}

// The frame interface. A frame (one file, vtkRelief*Frame.glsl, named by its mapper)
// turns a fragment's view ray into a ray in relief texture space and tells the fragment
// body where the hit lies; the body calls nothing else of it. A frame file defines
//   struct ReliefFrame, with at least
//     vec3 axisU, axisV: gradients of u and v in view space (a view-space direction d
//                        moves (u, v) by (dot(d, axisU), dot(d, axisV)))
//     vec3 normal:       the unit normal relief depth is measured along; with the axes,
//                        the shading basis
//     bool usable:       false where the frame holds no texture mapping (shaded plainly)
//   ReliefFrame reliefFrameOf(ReliefFragment fragment): the frame at a fragment, from the
//     frame's interpolated vertex data (fragment stage only)
//   bool reliefFrameHides(ReliefFrame, ReliefFragment): the fragment shows nothing
//   ReliefRay reliefFrameViewRay(ReliefFrame, ReliefFragment): its view ray
//   bool reliefFrameRayLeft(ReliefFrame, ReliefRay, ReliefHit): the ray that met nothing
//     left the surface past an outline (the fragment shows what lies behind)
//   float reliefFrameHitDistance(ReliefFrame, ReliefFragment, ReliefRay, ReliefHit): the
//     world distance from the fragment's point to the hit along the view direction
//   vec3 reliefFrameSurfaceSlope(ReliefFrame, ReliefFragment, float distance): the tilt
//     of the reference surface that far along the view ray (zero for flat frames)
// and, for the other stages, reliefFrameVertex() (vertex shader, after the position and
// texture coordinates are written) and the macro reliefFrameGeometry(vertex) (geometry
// shader, VTK's edges or the quadric mapper's vtkReliefTriangleGS.glsl: its unsized input
// arrays take loop indices only). The mapper defines RELIEF_VERTEX_STAGE,
// RELIEF_GEOMETRY_STAGE or RELIEF_FRAGMENT_STAGE before a frame's file; the CPU mirror
// defines none and compiles what holds no varyings.

// What every frame knows of its fragment: the rasteriser's and the mapper's part.
struct ReliefFragment
{
  vec3 viewVC;         // unit direction from the eye through it
  vec2 tcoord;         // texture coordinates there: the view ray's entry (finite)
  vec2 tcoordAlongX;   // their change to the next pixel along screen x (dFdx)
  vec2 tcoordAlongY;   // and along screen y (dFdy)
  vec3 positionAlongX; // the position's change to the next pixel along screen x
  vec3 positionAlongY; // and along screen y
  bool frontFacing;    // the side the mesh's winding faces is seen
  bool twoSided;       // back faces carry relief wherever they are drawn
  float depthScale;    // s_z: world depth of relief depth 1
  float deepest;       // the depth the search reaches: 1 for a height map, path features'
                       // deepest cut (RELIEF_DEEPEST)
  float eyeDistance;   // from the eye to the polygon's point (1e30 in parallel projection)
};

// A view-space direction in texture-space units (du, dv, ddepth) of a flat frame with
// the given axes and normal; depth grows inward.
vec3 reliefFlatDirection(vec3 directionVC, vec3 axisU, vec3 axisV, vec3 normal, float depthScale)
{
  return vec3(dot(directionVC, axisU), dot(directionVC, axisV),
    -dot(directionVC, normal) / depthScale);
}

// The world distance along the view direction to a hit of a flat frame's view ray
// (reliefViewRay of reliefFlatDirection): its depth over the ray's descent.
float reliefFlatHitDistance(vec3 viewVC, vec3 normal, float depthScale, ReliefHit hit)
{
  return hit.position.z * depthScale / max(-dot(viewVC, normal), 1e-6f);
}
