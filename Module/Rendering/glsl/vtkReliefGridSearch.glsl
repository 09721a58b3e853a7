// vtkRelief: the exact searches. They walk the ray over the cells of the bilinear height
// field (the patches between texel centres, Baboud and Decoret 2006, s3.1) and intersect it with a
// cell's patch by solving a quadratic, so no feature is missed, however thin.
// ExactDDA visits every cell the ray crosses (Baboud and Decoret 2006, s3.3, Amanatides and Woo);
// MaximumMipmap skips whole blocks of cells the ray passes over (Tevs, Ihrke and
// Seidel 2008). Shared with the CPU mirror; see vtkReliefCommon.glsl for the rules.
// MaximumMipmap also needs RELIEF_PYRAMID_DEPTH(node, level): the least depth (highest
// point) of a pyramid node, and RELIEF_PYRAMID_TOP, its top level.

#ifndef RELIEF_PYRAMID_DEPTH
// The GPU's pyramid: vtkMaximumMipmapFilter's atlas, one level of texture (a level's lod
// in texelFetch may be taken for a whole group of fragments by some drivers: llvmpipe),
// described by vtkReliefSearchMethod's uniforms.
uniform int reliefPyramidTop;
uniform float reliefPyramidRows[32]; // first atlas row of each level above 0
#define RELIEF_PYRAMID_TEXEL(node, level) vec4(texelFetch(reliefAccelerationTexture, \
  ivec2(node) + (level == 0 ? ivec2(0) : ivec2(reliefTextureSize.x, reliefPyramidRows[level])), 0))
#define RELIEF_PYRAMID_DEPTH(node, level) RELIEF_PYRAMID_TEXEL(node, level).r
#define RELIEF_PYRAMID_TOP reliefPyramidTop
// vtkSlopeMipmapFilter's atlas is uploaded (as integers) without its level 0, which
// SlopeMipmap never reads (it solves single cells from the height map): its other levels
// start at column 0
#define RELIEF_SLOPE_NODE(node, level) uvec4(texelFetch(reliefAccelerationTexture, \
  ivec2(node) + ivec2(0, reliefPyramidRows[level]), 0))
#endif

// Upper bound on loop iterations, so a shader always terminates.
#define RELIEF_MAX_ITERATIONS 65536

// The first parameter in [tIn, tOut] at which the ray is on or below the bilinear patch
// over cell (depths at its corners, see RELIEF_CELL_DEPTHS), or -1 when it stays above.
float reliefCellIntersection(ReliefGridRay grid, vec2 cell, vec4 depths, float tIn, float tOut)
{
  // the patch: depth(x, y) = a + b x + c y + e x y, x and y in [0, 1] across the cell
  float a = depths.x;
  float b = depths.y - depths.x;
  float c = depths.z - depths.x;
  float e = depths.w - depths.y - depths.z + depths.x;
  // the ray from tIn: (px + s qx, py + s qy) at depth z0 + s dz, s in [0, tOut - tIn]
  vec2 entry = reliefGridAt(grid, tIn);
  float px = entry.x - cell.x;
  float py = entry.y - cell.y;
  float qx = grid.direction.x;
  float qy = grid.direction.y;
  float z0 = grid.depth + tIn * grid.descent;
  // gap(s) = patch - ray depth = c0 + c1 s + c2 s^2; the first s where gap <= 0
  float c0 = a + b * px + c * py + e * px * py - z0;
  float c1 = b * qx + c * qy + e * (px * qy + py * qx) - grid.descent;
  float c2 = e * qx * qy;
  float span = tOut - tIn;
  if (c0 <= 0.0f)
  {
    return tIn;
  }
  float first = -1.0f;
  float discriminant = c1 * c1 - 4.0f * c2 * c0;
  if (discriminant >= 0.0f)
  {
    // the two roots without cancellation: q / c2 and c0 / q
    float root = sqrt(discriminant);
    float q = -0.5f * (c1 >= 0.0f ? c1 + root : c1 - root);
    float r1 = c2 != 0.0f ? q / c2 : -1.0f;
    float r2 = q != 0.0f ? c0 / q : -1.0f;
    float low = min(r1, r2);
    float high = max(r1, r2);
    first = low >= 0.0f ? low : high;
  }
  if (first >= 0.0f && first <= span)
  {
    return tIn + first;
  }
  // rounding can hide a root that the end of the cell still shows
  float endGap = c0 + span * (c1 + span * c2);
  return endGap <= 0.0f ? tOut : -1.0f;
}

// The depth gradient (change of depth per unit of u and v) at `uv`: that of the bilinear
// patch the searches intersect (the field between texel centres, Baboud and Decoret
// 2006, s3.1), read at full resolution from the cell under it, so that the surface lit is
// the surface searched.
vec2 reliefFieldGradient(vec2 uv)
{
  vec2 size = RELIEF_DEPTH_SIZE;
  vec2 at = vec2(uv.x * size.x - 0.5f, uv.y * size.y - 0.5f);
  vec2 cell = floor(at);
  vec2 within = at - cell;
  vec4 corners = RELIEF_CELL_DEPTHS(cell);
  return vec2(mix(corners.y - corners.x, corners.w - corners.z, within.y) * size.x,
    mix(corners.z - corners.x, corners.w - corners.y, within.x) * size.y);
}

// A parameter just before the first intersection t, hence above the field: the point the
// self-shadow ray aims at (at most 1e-3 in depth and 1/20 of a cell back).
float reliefClearBefore(ReliefGridRay grid, float t)
{
  float run = max(abs(grid.direction.x), abs(grid.direction.y));
  float back = min(1e-3f / max(abs(grid.descent), 1e-30f), 0.05f / max(run, 1e-30f));
  return max(0.0f, t - back);
}

ReliefHit reliefGridHit(ReliefRay ray, ReliefGridRay grid, float t, bool found, int samples)
{
  return reliefHitAt(ray, t, found ? reliefClearBefore(grid, t) : t, found, samples);
}

vec2 reliefStepSigns(ReliefGridRay grid)
{
  return vec2(grid.direction.x >= 0.0f ? 1.0f : -1.0f, grid.direction.y >= 0.0f ? 1.0f : -1.0f);
}

// Parameters per unit of texel coordinate along x and y (huge along an axis the ray
// does not move on).
vec2 reliefInverseRun(ReliefGridRay grid)
{
  return vec2(1.0f / max(abs(grid.direction.x), 1e-30f), 1.0f / max(abs(grid.direction.y), 1e-30f));
}

// The cell the ray goes on into from `cell`, whose next column and row it crosses at
// next.x and next.y (reliefCrossings).
vec2 reliefStepCell(vec2 cell, vec2 next, vec2 signs)
{
  return next.x < next.y ? vec2(cell.x + signs.x, cell.y) : vec2(cell.x, cell.y + signs.y);
}

// Parameters where the ray crosses x = bounds.x and y = bounds.y.
vec2 reliefCrossings(ReliefGridRay grid, vec2 bounds, vec2 signs, vec2 inverseRun)
{
  return vec2((bounds.x - grid.origin.x) * signs.x * inverseRun.x,
    (bounds.y - grid.origin.y) * signs.y * inverseRun.y);
}

// Every cell the ray's projection crosses between tStart and tEnd, in order, each
// intersected exactly (Baboud and Decoret 2006, s3.3 with the patch solved, not sampled): the first
// hit, or a miss at tEnd. `samples` counts on from the caller's.
ReliefHit reliefWalkCells(ReliefRay ray, ReliefGridRay grid, float tStart, float tEnd, int samples)
{
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  vec2 ahead = vec2(max(signs.x, 0.0f), max(signs.y, 0.0f));
  vec2 cell = floor(reliefGridAt(grid, tStart));
  float tIn = tStart;
  float tHit = -1.0f; // the hit, made into one after the loop, which stays small
  for (int i = 0; i < RELIEF_MAX_ITERATIONS; ++i)
  {
    // from the cell's own sides each time: summing steps drifts by a cell on rays
    // thousands of cells long, and the patch would be tested where the ray is not
    vec2 next = reliefCrossings(grid, cell + ahead, signs, inverseRun);
    float tOut = max(min(min(next.x, next.y), tEnd), tIn);
    samples += 1;
    tHit = reliefCellIntersection(grid, cell, RELIEF_CELL_DEPTHS(cell), tIn, tOut);
    if (tHit >= 0.0f || tOut >= tEnd)
    {
      break;
    }
    cell = reliefStepCell(cell, next, signs);
    tIn = tOut;
  }
  return tHit >= 0.0f ? reliefGridHit(ray, grid, tHit, true, samples)
                      : reliefGridHit(ray, grid, tEnd, false, samples);
}

// Field depth minus ray depth at t, from the cell under the ray: the polynomial that
// reliefCellIntersection solves, so that both agree on which side the ray is (a
// filtered read may round the other way).
float reliefCellGap(ReliefGridRay grid, float t)
{
  vec2 at = reliefGridAt(grid, t);
  vec2 cell = floor(at);
  vec4 depths = RELIEF_CELL_DEPTHS(cell);
  float x = at.x - cell.x;
  float y = at.y - cell.y;
  float b = depths.y - depths.x;
  float c = depths.z - depths.x;
  float e = depths.w - depths.y - depths.z + depths.x;
  return depths.x + b * x + c * y + e * x * y - (grid.depth + t * grid.descent);
}

// Brackets of at most this many cells (along the ray's major axis) are walked exactly;
// longer ones are halved first.
#define RELIEF_WALK_CELLS 2.0f

// The crossing in [above, below] of a ray above the field at `above`, on or below it at
// `below`, that enters the field once between (the bracket a safety radius or a cone
// gives): bisection down to RELIEF_WALK_CELLS cells, then an exact walk. `samples`
// counts on from the caller's. A bracket no longer than `span` in t ends the search at
// its far end, without the walk (the Automatic search's tolerance; 0: exact).
ReliefHit reliefRefineCrossingWithin(
  ReliefRay ray, ReliefGridRay grid, float above, float below, int samples, float span)
{
  float cellsPerT = max(abs(grid.direction.x), abs(grid.direction.y));
  for (int i = 0;
       i < 64 && (below - above) * cellsPerT > RELIEF_WALK_CELLS && below - above > span; ++i)
  {
    float middle = 0.5f * (above + below);
    samples += 1;
    if (reliefCellGap(grid, middle) <= 0.0f)
    {
      below = middle;
    }
    else
    {
      above = middle;
    }
  }
  if (span > 0.0f && below - above <= span)
  {
    // close enough: no walk; `above` is known above the field, the self-shadow's start
    return reliefHitAt(ray, below, above, true, samples);
  }
  ReliefHit walk = reliefWalkCells(ray, grid, above, below, samples);
  // the walk's own rounding may put the crossing a hair past `below`
  return walk.hit ? walk : reliefGridHit(ray, grid, below, true, walk.samples);
}

// The exact refinement.
ReliefHit reliefRefineCrossing(ReliefRay ray, ReliefGridRay grid, float above, float below, int samples)
{
  return reliefRefineCrossingWithin(ray, grid, above, below, samples, 0.0f);
}

// The end of a search that met nothing before t = 1: a view ray is as deep as the deepest
// level there, so it ends on the field (a floor at depth 1 is met exactly there, and
// rounding may let the cell tests pass it by).
ReliefHit reliefGridEnd(ReliefRay ray, ReliefGridRay grid, int samples)
{
  return reliefGridHit(ray, grid, 1.0f, grid.depth + grid.descent >= 1.0f, samples);
}

// ExactDDA: the whole ray, cell by cell.
ReliefHit reliefSearchExactDDA(ReliefRay ray, int linearSteps, int refinementSteps)
{
  ReliefGridRay grid = reliefGridRay(ray, RELIEF_DEPTH_SIZE);
  ReliefHit hit = reliefWalkCells(ray, grid, 0.0f, 1.0f, 0);
  return hit.hit ? hit : reliefGridEnd(ray, grid, hit.samples);
}

// MaximumMipmap: a quadtree of the cells, each node holding the least depth of the
// cells below it (vtkMaximumMipmapFilter). A node the ray passes over without reaching
// that depth is skipped whole; otherwise the ray descends into it, down to single cells,
// which are intersected exactly. Level L has GL's mipmap size max(1, size >> L); node i
// covers cells [i 2^L, (i + 1) 2^L), the last node of a row everything to the tile's
// edge, so sizes need not be powers of two.
// Nodes per axis at `level`, computed rather than asked of the texture: some GL drivers
// answer textureSize for one level per group of fragments.
vec2 reliefPyramidSize(int level)
{
  vec2 size = floor(RELIEF_DEPTH_SIZE / float(1 << level));
  return vec2(max(size.x, 1.0f), max(size.y, 1.0f));
}

// The level whose nodes span about the ray's whole run (any level will do, so a driver's
// inexact log2 costs nothing).
int reliefPyramidRunLevel(ReliefGridRay grid)
{
  float run = max(abs(grid.direction.x), abs(grid.direction.y));
  return int(ceil(log2(max(run, 1.0f))));
}

// The corner past node `node` of `level` in the tile whose first cell is `origin`: a span
// on from the node's first cell, or the tile's edge for the last node of a row.
vec2 reliefPyramidNodeEnd(vec2 node, int level, vec2 origin)
{
  float span = float(1 << level); // exact, unlike exp2 on some GPUs
  vec2 levelSize = reliefPyramidSize(level);
  vec2 size = RELIEF_DEPTH_SIZE;
  return vec2(node.x >= levelSize.x - 1.0f ? origin.x + size.x : origin.x + (node.x + 1.0f) * span,
    node.y >= levelSize.y - 1.0f ? origin.y + size.y : origin.y + (node.y + 1.0f) * span);
}

// Where the ray leaves the cells [low, high), across x and across y.
vec2 reliefBoxExits(ReliefGridRay grid, vec2 low, vec2 high, vec2 signs, vec2 inverseRun)
{
  return reliefCrossings(grid,
    vec2(signs.x > 0.0f ? high.x : low.x, signs.y > 0.0f ? high.y : low.y), signs, inverseRun);
}

vec2 reliefPyramidParent(vec2 node, int level)
{
  vec2 parentSize = reliefPyramidSize(level + 1);
  return min(floor(0.5f * node), vec2(parentSize.x - 1.0f, parentSize.y - 1.0f));
}

ReliefHit reliefSearchMaximumMipmap(ReliefRay ray, int linearSteps, int refinementSteps)
{
  vec2 size = RELIEF_DEPTH_SIZE;
  ReliefGridRay grid = reliefGridRay(ray, size);
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  // start at the level whose nodes span about the ray's whole run, not at the root: a
  // steep ray has no long stretch to skip, and would only pay the descent
  int level = min(RELIEF_PYRAMID_TOP, reliefPyramidRunLevel(grid));
  vec2 tile = floor(vec2(grid.origin.x / size.x, grid.origin.y / size.y));
  vec2 startSize = reliefPyramidSize(level);
  vec2 node = min(floor((grid.origin - vec2(tile.x * size.x, tile.y * size.y)) / float(1 << level)),
    vec2(startSize.x - 1.0f, startSize.y - 1.0f));
  float t = 0.0f;
  int samples = 0;
  float tHit = -1.0f; // the hit, made into one after the loop, which stays small
  for (int i = 0; i < RELIEF_MAX_ITERATIONS; ++i)
  {
    // the node's cells, as texel coordinates
    float span = float(1 << level); // exact, unlike exp2 on some GPUs
    vec2 levelSize = reliefPyramidSize(level);
    vec2 origin = vec2(tile.x * size.x, tile.y * size.y);
    vec2 low = origin + node * span;
    vec2 exits = reliefBoxExits(grid, low, reliefPyramidNodeEnd(node, level, origin), signs,
      inverseRun);
    float tOut = min(exits.x, exits.y);
    samples += 1;
    // where the ray reaches the node's top: a ray that descends, by the node's far side,
    // from tReach on; one that rises (the impostor's views behind it), at its near side
    float top = RELIEF_PYRAMID_DEPTH(node, level);
    float tReach = grid.descent > 0.0f ? (top - grid.depth) / grid.descent : t;
    bool reaches = grid.descent > 0.0f ? tReach <= min(tOut, 1.0f)
                                       : grid.depth + t * grid.descent >= top;
    if (reaches)
    {
      if (level == 0)
      {
        samples += 1;
        tHit = reliefCellIntersection(
          grid, low, RELIEF_CELL_DEPTHS(low), max(t, tReach), max(min(tOut, 1.0f), t));
        if (tHit >= 0.0f)
        {
          break;
        }
      }
      else
      {
        // down into the child under the ray where it reaches the node's top; rounding
        // must never pick the child ahead (its part before would be skipped), so ask
        // just behind: a child behind is left again at once, by the neighbour step
        t = max(t, tReach);
        vec2 at = reliefGridAt(grid, t) - 1e-3f * signs;
        level -= 1;
        float childSpan = 0.5f * span;
        vec2 childSize = reliefPyramidSize(level);
        vec2 lastChild = vec2(node.x >= levelSize.x - 1.0f ? childSize.x - 1.0f : 2.0f * node.x + 1.0f,
          node.y >= levelSize.y - 1.0f ? childSize.y - 1.0f : 2.0f * node.y + 1.0f);
        node = clamp(floor((at - origin) / childSpan), 2.0f * node, lastChild);
        continue;
      }
    }
    // past the node: on to its neighbour across the side the ray leaves by, and up a
    // level when that neighbour has another parent
    t = max(t, tOut);
    if (t >= 1.0f)
    {
      break;
    }
    vec2 parent = level < RELIEF_PYRAMID_TOP ? reliefPyramidParent(node, level) : node;
    vec2 oldTile = tile;
    if (exits.x < exits.y)
    {
      node.x += signs.x;
      tile.x += node.x < 0.0f ? -1.0f : (node.x >= levelSize.x ? 1.0f : 0.0f);
      node.x = node.x < 0.0f ? levelSize.x - 1.0f : (node.x >= levelSize.x ? 0.0f : node.x);
    }
    else
    {
      node.y += signs.y;
      tile.y += node.y < 0.0f ? -1.0f : (node.y >= levelSize.y ? 1.0f : 0.0f);
      node.y = node.y < 0.0f ? levelSize.y - 1.0f : (node.y >= levelSize.y ? 0.0f : node.y);
    }
    if (level < RELIEF_PYRAMID_TOP)
    {
      vec2 newParent = reliefPyramidParent(node, level);
      if (newParent != parent || tile != oldTile)
      {
        node = newParent;
        level += 1;
      }
    }
  }
  return tHit >= 0.0f ? reliefGridHit(ray, grid, tHit, true, samples)
                      : reliefGridEnd(ray, grid, samples);
}
