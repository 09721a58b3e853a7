// vtkRelief: SlopeMipmap, an exact search over a maximum mipmap whose nodes also bound the
// slopes of the field under them (vtkSlopeMipmapFilter). MaximumMipmap (Tevs et al. 2008) can
// only skip a node the ray passes over entirely; with the box of the field's gradients the gap
// g(t) = field depth - ray depth changes at a rate within [least, most] across the node, so
// one read of a node the ray is standing above (g >= gLow >= 0 at t) proves more:
//  (a) the ray leaves the node above its top: over it (MaximumMipmap's test);
//  (b) least >= 0: the gap cannot fall in the node: over it;
//  (c) gLow + least * (tOut - t) > 0: the gap cannot fall to 0 before the exit (a Lipschitz
//      bound, after segment tracing, Galin et al. 2020): over it, with that bound carried on;
//  (d) most < 0: the gap only falls, so the ray meets the field at most once in the node:
//      none where the ray clears the top of the grandchild at the exit; else the node's cells
//      are read, the first in the first grandchild whose top the ray does not clear (of the
//      three after where it reaches the node's top; else at the exit), the next where Newton
//      from the last (left above the field) puts the crossing, until one holds it, or is
//      entered below the field (a bracket), or the gap's bound clears the rest;
// otherwise down a level, where the ray reaches the node's top. A node's texel also holds its
// sixteen grandchildren's tops, and so its children's: while it is in hand, a child or
// grandchild the ray clears (by its top, or by the node's Lipschitz bound) is passed over
// without a read, and the search goes down through a child it does not clear without reading
// it, so one read buys three levels' worth of tests. Two texels are kept in hand, the last
// one gone down into and the one before, for the siblings of the nodes under the first.
// Single cells are solved as ExactDDA does. A bracket [above, below] holding one crossing is
// closed by reading cells where Newton's estimate or, with the gap and its rate known at both
// ends, a cubic Hermite interpolant's root puts it, within what the rates allow, each read
// solving the whole cell: with one crossing, the first zero of a cell entered above the field
// is it. Exact: every skip is proven, every hit solved from a point known above the field.
// Shared with the CPU mirror; see vtkReliefCommon.glsl for the rules. Needs
// vtkReliefGridSearch.glsl (its pyramid's levels) and vtkReliefSafetySearch.glsl
// (reliefCellAfter) before it, and RELIEF_SLOPE_NODE(node, level): the uvec4 of a node above
// level 0 (vtkSlopeMipmapFilter::PackNode), unpacked by reliefSlopeNodeOf (the GPU's in
// vtkReliefGridSearch.glsl).

// One 10-bit code of vtkSlopeMipmapFilter::EncodeSlopes: 512 is 0, each code away from it
// one 30th of an octave from 2^-15.
float reliefSlopeValue(uint code)
{
  float steps = float(code) - 512.0f;
  return steps == 0.0f ? 0.0f : sign(steps) * exp2(abs(steps) / 30.0f - 15.0f);
}

// Two slope bounds packed in the low 20 bits of `codes`: low + 1024 high.
vec2 reliefSlopeDecode(uint codes)
{
  return vec2(reliefSlopeValue(codes & 1023u), reliefSlopeValue((codes >> 10u) & 1023u));
}

// The least and most rate of the gap along the ray (per unit of t) over a node whose
// texel (vtkSlopeMipmapFilter::PackNode) is `texel`.
vec2 reliefSlopeRates(uvec4 texel, ReliefGridRay grid)
{
  vec2 x = reliefSlopeDecode(texel.y) * grid.direction.x;
  vec2 y = reliefSlopeDecode(texel.z) * grid.direction.y;
  return vec2(min(x.x, x.y) + min(y.x, y.y) - grid.descent,
    max(x.x, x.y) + max(y.x, y.y) - grid.descent);
}

// A node's texel as the search holds it: its level (-1: none), its box of cells
// (unwrapped: the tile's), its top, the least rate of the gap along the ray over it and its
// grandchildren's coded tops (vtkSlopeMipmapFilter::EncodeGrandchildTops).
struct ReliefSlopeNode
{
  int level;
  vec2 low;
  vec2 high;
  float top;
  float leastRate;
  float step;  // the grandchildren's codes' unit
  uvec2 codes; // codes 0 to 7 and 8 to 15, 4 bits each
};

ReliefSlopeNode reliefSlopeNone()
{
  ReliefSlopeNode none;
  none.level = -1;
  none.low = vec2(0.0f, 0.0f);
  none.high = vec2(0.0f, 0.0f);
  none.top = 0.0f;
  none.leastRate = 0.0f;
  none.step = 0.0f;
  none.codes = uvec2(0u, 0u);
  return none;
}

// The texel of vtkSlopeMipmapFilter::PackNode unpacked, but for its slopes (reliefSlopeRates):
// bit fields are taken with shifts, and the top and the step are exact in a float.
ReliefSlopeNode reliefSlopeNodeOf(uvec4 texel, int level, vec2 low, vec2 high, float leastRate)
{
  ReliefSlopeNode held;
  held.level = level;
  held.low = low;
  held.high = high;
  held.top = float(texel.x & 1048575u) * (1.0f / 1048576.0f);
  held.leastRate = leastRate;
  held.step = 1.0f / float(1u << (((texel.x >> 20u) & 15u) + 4u));
  held.codes =
    uvec2(texel.w, (texel.y >> 20u) | ((texel.z >> 20u) << 12u) | ((texel.x >> 24u) << 24u));
  return held;
}

// The top of the grandchild in `slot` (offsets from the first, at most 3) of a node in hand:
// at most the grandchild's. Code x + 4 y lies at bit 4 (x + 4 y) of the 64 of `codes`.
float reliefSlopeGrandchildTop(ReliefSlopeNode held, vec2 slot)
{
  int y = int(slot.y);
  uint word = y < 2 ? held.codes.x : held.codes.y;
  return held.top + float((word >> uint(4 * int(slot.x) + 16 * (y & 1))) & 15u) * held.step;
}

// The top of the child at `offset` (from the first, at most 1: the last node's folded third
// child shares the second's slots) of a node in hand: the least of its four grandchildren's
// codes, which lie in one word at bits 0, 4, 16 and 20 from 8 offset.x.
float reliefSlopeChildTop(ReliefSlopeNode held, vec2 offset)
{
  uint quad = (offset.y > 0.0f ? held.codes.y : held.codes.x) >> uint(8.0f * offset.x);
  uint least =
    min(min(quad & 15u, (quad >> 4u) & 15u), min((quad >> 16u) & 15u, (quad >> 20u) & 15u));
  return held.top + float(least) * held.step;
}

// 1 where the node in hand is the parent of the node of `level` holding `cell`, 2 where it
// is its grandparent, else 0: nodes nest, so the node in hand is an ancestor where its box
// holds the cell.
int reliefSlopeGeneration(ReliefSlopeNode held, vec2 cell, int level)
{
  bool holds = cell.x >= held.low.x && cell.y >= held.low.y && cell.x < held.high.x &&
    cell.y < held.high.y;
  return holds && held.level > level && held.level <= level + 2 ? held.level - level : 0;
}

// The top of a node (its first cell `low`, `span` cells a side) from its parent's or
// grandparent's texel (`generation`): its offset in nodes from the held node's first
// descendant of its level, a whole number (rounded, should a division land below it),
// picks the slot.
float reliefSlopeKnownTop(ReliefSlopeNode held, vec2 low, float span, int generation)
{
  vec2 offset = floor((low - held.low) / span + 0.5f);
  return generation == 2 ? reliefSlopeGrandchildTop(held, min(offset, vec2(3.0f, 3.0f)))
                         : reliefSlopeChildTop(held, min(offset, vec2(1.0f, 1.0f)));
}

// The gap and its rate (per unit of t) at t, on the patch of `cell`.
vec2 reliefPatchGap(ReliefGridRay grid, vec2 cell, vec4 depths, float t)
{
  vec2 at = reliefGridAt(grid, t);
  float x = at.x - cell.x;
  float y = at.y - cell.y;
  float b = depths.y - depths.x;
  float c = depths.z - depths.x;
  float e = depths.w - depths.y - depths.z + depths.x;
  float gap = depths.x + b * x + c * y + e * x * y - (grid.depth + t * grid.descent);
  float rate = (b + e * y) * grid.direction.x + (c + e * x) * grid.direction.y - grid.descent;
  return vec2(gap, rate);
}

// The root in [0, 1] of the cubic Hermite interpolant of a gap that falls from g0 > 0 to
// g1 < 0 over [0, 1], with slopes d0 and d1 there: Newton's method on the cubic from the
// secant's root (no read: a guess where to read).
float reliefHermiteRoot(float g0, float d0, float g1, float d1)
{
  float s = g0 / (g0 - g1);
  for (int i = 0; i < 4; ++i)
  {
    float s2 = s * s;
    float s3 = s2 * s;
    float value = (2.0f * s3 - 3.0f * s2 + 1.0f) * g0 + (s3 - 2.0f * s2 + s) * d0 +
      (3.0f * s2 - 2.0f * s3) * g1 + (s3 - s2) * d1;
    float slope = (6.0f * s2 - 6.0f * s) * (g0 - g1) + (3.0f * s2 - 4.0f * s + 1.0f) * d0 +
      (3.0f * s2 - 2.0f * s) * d1;
    s = slope < 0.0f ? min(max(s - value / slope, 0.0f), 1.0f) : s;
  }
  return s;
}

// Where the ray crosses the column and the row it enters `cell` by, unclamped.
vec2 reliefSlopeCellEntries(ReliefGridRay grid, vec2 cell, vec2 signs, vec2 inverseRun)
{
  return reliefCrossings(grid,
    vec2(cell.x + 1.0f - max(signs.x, 0.0f), cell.y + 1.0f - max(signs.y, 0.0f)), signs,
    inverseRun);
}

// Where the ray enters and leaves `cell`: (entry, exit), unclamped.
vec2 reliefSlopeCellSpan(ReliefGridRay grid, vec2 cell, vec2 signs, vec2 inverseRun)
{
  vec2 entries = reliefSlopeCellEntries(grid, cell, signs, inverseRun);
  vec2 exits = reliefBoxExits(grid, cell, cell + 1.0f, signs, inverseRun);
  return vec2(max(entries.x, entries.y), min(exits.x, exits.y));
}

// The cell the ray is in before it enters `cell`: across the later of its two entries, or
// across both where they tie (through a corner, a cell beside it meets the ray only there).
vec2 reliefSlopeCellBehind(ReliefGridRay grid, vec2 cell, vec2 signs, vec2 inverseRun)
{
  vec2 entries = reliefSlopeCellEntries(grid, cell, signs, inverseRun);
  float entry = max(entries.x, entries.y);
  return vec2(entries.x >= entry ? cell.x - signs.x : cell.x,
    entries.y >= entry ? cell.y - signs.y : cell.y);
}

// The crossing in [above, below], where the gap falls all along (at a rate within
// `rates`, rates.y < 0), so there is one, and every point before it is above the field:
// gap and rate known at `below` (gapBelow, gap < 0) and, where gapAbove.x > 0, at `above`.
// Each probe reads the cell where the Hermite interpolant (gap and rate known at both ends)
// or Newton (from below) puts the crossing, bounded by the rates, and solves it over its
// part of the bracket: the crossing, or a new end with its gap and rate known exactly; when
// two probes have not halved the bracket, a bisection follows. A bracket no longer than
// `endSpan` in t ends the search at its far end (the Automatic search's tolerance; 0: exact).
ReliefHit reliefSlopeRefine(ReliefRay ray, ReliefGridRay grid, float above, float below,
  vec2 gapAbove, vec2 gapBelow, vec2 rates, int samples, float endSpan)
{
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  float lastWidth = 2.0f * (below - above);
  float olderWidth = lastWidth;
  for (int i = 0; i < 64 && above < below; ++i)
  {
    if (below - above <= endSpan)
    {
      // close enough: `above` is known above the field, the self-shadow's start
      return reliefHitAt(ray, below, above, true, samples);
    }
    float low = max(above, below - gapBelow.x / rates.y);
    float high = min(below, below - gapBelow.x / rates.x);
    if (gapAbove.x > 0.0f)
    {
      low = max(low, above - gapAbove.x / rates.x);
      high = min(high, above - gapAbove.x / rates.y);
    }
    float width = below - above;
    float estimate = gapAbove.x > 0.0f
      ? above +
        width * reliefHermiteRoot(gapAbove.x, gapAbove.y * width, gapBelow.x, gapBelow.y * width)
      : (gapBelow.y < 0.0f ? below - gapBelow.x / gapBelow.y : 0.5f * (low + high));
    // rounding may cross the bounds: then `high` (GLSL's clamp is undefined there), and
    // `high` may round below `above`: the probe stays in the bracket
    float probe = max(
      min(max(width > 0.5f * olderWidth ? 0.5f * (low + high) : estimate, low), high), above);
    olderWidth = lastWidth;
    lastWidth = width;
    // the cell the ray enters at the probe, so that its part of the bracket is not empty;
    // at the bracket's far end (the crossing there within rounding), the one before
    vec2 cell = reliefCellAfter(grid, probe, signs, inverseRun);
    vec2 cellSpan = reliefSlopeCellSpan(grid, cell, signs, inverseRun);
    if (cellSpan.x >= below)
    {
      cell = reliefSlopeCellBehind(grid, cell, signs, inverseRun);
      cellSpan = reliefSlopeCellSpan(grid, cell, signs, inverseRun);
    }
    float tIn = min(max(cellSpan.x, above), probe);
    float tOut = max(min(cellSpan.y, below), probe);
    vec4 depths = RELIEF_CELL_DEPTHS(cell);
    samples += 1;
    float t = reliefCellIntersection(grid, cell, depths, tIn, tOut);
    if (t > tIn || (t >= 0.0f && tIn <= above))
    {
      return reliefGridHit(ray, grid, t, true, samples);
    }
    if (t >= 0.0f)
    {
      below = tIn;
      gapBelow = reliefPatchGap(grid, cell, depths, tIn);
      if (gapBelow.x >= 0.0f)
      {
        // on the field at the cell's entry, within rounding: that is the crossing
        return reliefGridHit(ray, grid, tIn, true, samples);
      }
    }
    else
    {
      above = tOut;
      gapAbove = reliefPatchGap(grid, cell, depths, tOut);
      gapAbove.x = max(gapAbove.x, 1e-30f);
    }
  }
  // float rounding closed the bracket: an exact walk of what is left
  ReliefHit walk = reliefWalkCells(ray, grid, min(above, below), below, samples);
  return walk.hit ? walk : reliefGridHit(ray, grid, below, true, walk.samples);
}

// A node where the gap only falls (case (d)), searched by reading cells: its exit and box,
// the gap's rates over it, the cell the search entered it by (to climb out from), the last
// point known above the field and the gap and its rate there (x <= 0: not known), the point
// the next read is at, in the cell there within [probeLow, probeHigh), and the widths of
// the span the last two reads left a crossing in (a bisection when two have not halved it).
struct ReliefSlopeFall
{
  bool searching;
  float exit;
  vec2 low;
  vec2 high;
  vec2 rates;
  vec2 entryCell;
  float above;
  vec2 gapAbove;
  float probe;
  vec2 probeLow;
  vec2 probeHigh;
  float lastWidth;
  float olderWidth;
};

ReliefSlopeFall reliefSlopeFallNone()
{
  ReliefSlopeFall none;
  none.searching = false;
  none.exit = 0.0f;
  none.low = vec2(0.0f, 0.0f);
  none.high = vec2(0.0f, 0.0f);
  none.rates = vec2(0.0f, 0.0f);
  none.entryCell = vec2(0.0f, 0.0f);
  none.above = 0.0f;
  none.gapAbove = vec2(-1.0f, 0.0f);
  none.probe = 0.0f;
  none.probeLow = vec2(0.0f, 0.0f);
  none.probeHigh = vec2(0.0f, 0.0f);
  none.lastWidth = 2.0f;
  none.olderWidth = 2.0f;
  return none;
}

// A walk along the ray over the sixteen grandchildren of a node of case (d): the slot it is
// at, from where, and once it has found the first grandchild whose top the ray does not
// clear, where the first read goes (ReliefSlopeFall's probe and its box).
struct ReliefSlopeWalk
{
  vec2 slot;
  float from;
  bool found;
  float probe;
  vec2 probeLow;
  vec2 probeHigh;
};

// One grandchild of the walk (the last a side reaching the node's end): where the ray does
// not clear its top, the read goes three quarters of the way into it from where the ray
// reaches that top (no crossing lies before it), so that Newton reaches less far than from
// the node's exit; else on to the next grandchild along the ray.
ReliefSlopeWalk reliefSlopeWalkStep(ReliefSlopeWalk walk, ReliefSlopeNode held,
  ReliefGridRay grid, vec2 signs, vec2 inverseRun, float tOut, float quarter)
{
  vec2 slotLow = held.low + walk.slot * quarter;
  vec2 slotHigh = vec2(walk.slot.x >= 3.0f ? held.high.x : slotLow.x + quarter,
    walk.slot.y >= 3.0f ? held.high.y : slotLow.y + quarter);
  vec2 borders = reliefCrossings(grid,
    vec2(signs.x > 0.0f ? slotHigh.x : slotLow.x, signs.y > 0.0f ? slotHigh.y : slotLow.y),
    signs, inverseRun);
  float slotOut = min(max(min(borders.x, borders.y), walk.from), tOut);
  float top = reliefSlopeGrandchildTop(held, walk.slot);
  bool stops = !walk.found && (grid.depth + slotOut * grid.descent >= top || slotOut >= tOut);
  bool steps = !walk.found && !stops;
  float reaches = min(max((top - grid.depth) / grid.descent, walk.from), slotOut);
  walk.probe = stops ? reaches + 0.75f * (slotOut - reaches) : walk.probe;
  walk.probeLow = stops ? slotLow : walk.probeLow;
  walk.probeHigh = stops ? min(slotHigh, held.high) : walk.probeHigh;
  walk.from = steps ? slotOut : walk.from;
  walk.slot = steps ? (borders.x < borders.y ? vec2(walk.slot.x + signs.x, walk.slot.y)
                                             : vec2(walk.slot.x, walk.slot.y + signs.y))
                    : walk.slot;
  walk.found = walk.found || stops;
  return walk;
}

// Case (d) in the node in hand `held`, entered by `cell` at t, left at tOut, its gap's rates
// `rates`: the first read in the first grandchild along the ray whose top the ray does not
// clear (reliefSlopeWalkStep). Before the ray reaches the node's top it clears every
// grandchild's, and from there it seldom clears more than two: three are looked at, in
// straight code, as a loop in the search's loop costs every pass (on llvmpipe, which runs
// all of a loop's body for a SIMD group, a walk of seven in a loop took 1.4 times the frame
// time of none, three unrolled 1.2 times; seven saved 0.5% of the samples). Else, and where
// grandchildren are not whole cells (nodes under four cells a side) or the node lies
// within `endSpan` (as a bracket would end there), at the node's exit.
ReliefSlopeFall reliefSlopeFallInto(ReliefSlopeNode held, ReliefGridRay grid, vec2 signs,
  vec2 inverseRun, vec2 cell, float t, float tOut, vec2 rates, float endSpan)
{
  ReliefSlopeFall fall = reliefSlopeFallNone();
  fall.searching = true;
  fall.exit = tOut;
  fall.low = held.low;
  fall.high = held.high;
  fall.rates = rates;
  fall.entryCell = cell;
  fall.above = t;
  fall.probe = tOut;
  fall.probeLow = held.low;
  fall.probeHigh = held.high;
  float quarter = float(1 << held.level) * 0.25f;
  if (quarter < 1.0f || tOut - t <= endSpan)
  {
    return fall;
  }
  ReliefSlopeWalk walk;
  walk.from = max(t, min((held.top - grid.depth) / grid.descent, tOut));
  vec2 at =
    min(max(reliefCellAfter(grid, walk.from, signs, inverseRun), held.low), held.high - 1.0f);
  walk.slot = min(floor((at - held.low) / quarter), vec2(3.0f, 3.0f));
  walk.found = false;
  walk.probe = tOut;
  walk.probeLow = held.low;
  walk.probeHigh = held.high;
  walk = reliefSlopeWalkStep(walk, held, grid, signs, inverseRun, tOut, quarter);
  walk = reliefSlopeWalkStep(walk, held, grid, signs, inverseRun, tOut, quarter);
  walk = reliefSlopeWalkStep(walk, held, grid, signs, inverseRun, tOut, quarter);
  fall.probe = walk.probe;
  fall.probeLow = walk.probeLow;
  fall.probeHigh = walk.probeHigh;
  return fall;
}

// The cell of level 0 that the ray is in from t to tOut, searched as a node where the gap
// only falls is: one read, whatever its rates.
ReliefSlopeFall reliefSlopeFallCell(vec2 cell, float t, float tOut)
{
  ReliefSlopeFall fall = reliefSlopeFallNone();
  fall.searching = true;
  fall.exit = tOut;
  fall.low = cell;
  fall.high = cell + 1.0f;
  fall.entryCell = cell;
  fall.above = t;
  fall.probe = t;
  fall.probeLow = cell;
  fall.probeHigh = cell + 1.0f;
  return fall;
}

// The level the search goes on at past a node of `level` that holds `cell`, left at tOut:
// one up where the cell after it has another parent, or lies in another tile.
int reliefSlopeLevelPast(ReliefGridRay grid, vec2 signs, vec2 inverseRun, vec2 cell, float tOut,
  int level, vec2 size)
{
  vec2 next = reliefCellAfter(grid, tOut, signs, inverseRun);
  vec2 tile = floor(vec2(cell.x / size.x, cell.y / size.y));
  vec2 origin = vec2(tile.x * size.x, tile.y * size.y);
  float parentSpan = float(2 << level);
  bool climbs = floor(next.x / size.x) != tile.x || floor(next.y / size.y) != tile.y ||
    floor((next.x - origin.x) / parentSpan) != floor((cell.x - origin.x) / parentSpan) ||
    floor((next.y - origin.y) / parentSpan) != floor((cell.y - origin.y) / parentSpan);
  return climbs ? min(level + 1, RELIEF_PYRAMID_TOP) : level;
}

// The search; a bracket no longer than `endSpan` in t ends it at its far end (0: exact).
// Each pass of the loop takes one node, by the texels in hand or by its own, read, and reads
// a cell where one is needed: one of level 0, or one of a node of (d), the first in the same
// pass as the node's texel. Cells are read at one place in the body, as a SIMD group of
// fragments runs all of it whichever branches they take (llvmpipe does).
ReliefHit reliefSlopeMipmapWithin(ReliefRay ray, float endSpan)
{
  vec2 size = RELIEF_DEPTH_SIZE;
  ReliefGridRay grid = reliefGridRay(ray, size);
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  // start a level below the one whose nodes span the ray's whole run: the slopes prove
  // more in smaller nodes, and climbing is cheap
  int level = clamp(reliefPyramidRunLevel(grid) - 1, 0, RELIEF_PYRAMID_TOP);
  float t = 0.0f;
  float gapLow = 0.0f; // a lower bound of the gap at t
  int samples = 0;
  // the texels in hand: the last node gone down into, and the one before it
  ReliefSlopeNode inner = reliefSlopeNone();
  ReliefSlopeNode outer = reliefSlopeNone();
  ReliefSlopeFall fall = reliefSlopeFallNone();
  // the outcome, acted on after the loop so that the loop body stays small: a hit at tHit,
  // or a crossing bracketed in [bracketStart, tHit], with the gaps and rates there
  float tHit = -1.0f;
  float bracketStart = -1.0f;
  vec2 bracketGapAbove = vec2(-1.0f, 0.0f);
  vec2 bracketGapBelow = vec2(0.0f, 0.0f);
  vec2 bracketRates = vec2(0.0f, 0.0f);
  for (int i = 0; i < RELIEF_MAX_ITERATIONS && t < 1.0f; ++i)
  {
    // past a node at the end of the pass: the one holding passCell, to passExit, with the
    // gap at least passLow there
    bool passes = false;
    vec2 passCell = vec2(0.0f, 0.0f);
    float passExit = 0.0f;
    float passLow = 0.0f;
    if (!fall.searching)
    {
      vec2 cell = reliefCellAfter(grid, t, signs, inverseRun);
      vec2 tile = floor(vec2(cell.x / size.x, cell.y / size.y));
      vec2 origin = vec2(tile.x * size.x, tile.y * size.y);
      float span = float(1 << level); // exact, unlike exp2 on some GPUs
      vec2 levelSize = reliefPyramidSize(level);
      vec2 node =
        min(floor((cell - origin) / span), vec2(levelSize.x - 1.0f, levelSize.y - 1.0f));
      vec2 low = origin + node * span;
      vec2 high = reliefPyramidNodeEnd(node, level, origin);
      vec2 exits = reliefBoxExits(grid, low, high, signs, inverseRun);
      float tOut = min(max(min(exits.x, exits.y), t), 1.0f);
      float zOut = grid.depth + tOut * grid.descent;
      bool over = false;
      float nextLow = 0.0f;
      // a texel in hand that knows the node's top
      ReliefSlopeNode known = inner;
      int generation = reliefSlopeGeneration(inner, cell, level);
      if (generation == 0)
      {
        known = outer;
        generation = reliefSlopeGeneration(outer, cell, level);
      }
      if (generation > 0)
      {
        float top = reliefSlopeKnownTop(known, low, span, generation);
        float bound = gapLow + known.leastRate * (tOut - t);
        over = zOut < top || bound > 0.0f;
        nextLow = max(max(top - zOut, bound), 0.0f);
        if (!over && generation == 1 && level > 0)
        {
          // down without a read, where the ray reaches the node's top: the texel in hand
          // knows its children's tops too
          float tDown = max(t, min((top - grid.depth) / grid.descent, tOut));
          gapLow = max(gapLow + known.leastRate * (tDown - t), 0.0f);
          t = tDown;
          level -= 1;
          continue;
        }
      }
      if (!over && level > 0)
      {
        samples += 1;
        uvec4 texel = RELIEF_SLOPE_NODE(node, level);
        vec2 rates = reliefSlopeRates(texel, grid);
        ReliefSlopeNode read = reliefSlopeNodeOf(texel, level, low, high, rates.x);
        float bound = gapLow + rates.x * (tOut - t); // the gap at the exit is at least this
        over = zOut < read.top || rates.x >= 0.0f || bound > 0.0f;
        nextLow = max(max(read.top - zOut, bound), 0.0f);
        if (!over && rates.y < 0.0f)
        {
          // (d): a gap that only falls and is still open at the exit was open all along:
          // the exit's grandchild says so when the ray clears its top there (the exit's
          // cell the node's whatever side of the border rounding puts the exit); else
          // cells are read, from the first the node's grandchildren point to
          vec2 exitCell = min(max(floor(reliefGridAt(grid, tOut)), low), high - 1.0f);
          float exitTop = reliefSlopeGrandchildTop(
            read, min(floor((exitCell - low) / (0.25f * span)), vec2(3.0f, 3.0f)));
          over = zOut < exitTop;
          nextLow = max(exitTop - zOut, nextLow);
          if (!over)
          {
            fall = reliefSlopeFallInto(
              read, grid, signs, inverseRun, cell, t, tOut, rates, endSpan);
          }
        }
        else if (!over)
        {
          // down, where the ray reaches the node's top, the gap bound carried there, with
          // the node's texel in hand (a texel passed over stays out of hand, so that the
          // ones in hand still serve its siblings)
          outer = inner;
          inner = read;
          float tDown = max(t, min((read.top - grid.depth) / grid.descent, tOut));
          gapLow = max(gapLow + rates.x * (tDown - t), 0.0f);
          t = tDown;
          level -= 1;
          continue;
        }
      }
      else if (!over)
      {
        fall = reliefSlopeFallCell(cell, t, tOut);
      }
      passes = over;
      passCell = cell;
      passExit = tOut;
      passLow = nextLow;
    }
    if (fall.searching)
    {
      // one cell read, solved over its part of the node: with one crossing in the node, a
      // zero is it, a cell entered below the field brackets it, and a cell left above the
      // field tells the gap and its rate there exactly
      // the cell the ray enters at the probe (on a border the one ahead, so that a probe
      // at the last cell's exit reads the next), within the probe's box for rounding
      vec2 cell = min(max(reliefCellAfter(grid, fall.probe, signs, inverseRun), fall.probeLow),
        fall.probeHigh - 1.0f);
      vec2 cellSpan = reliefSlopeCellSpan(grid, cell, signs, inverseRun);
      float cellIn = min(max(cellSpan.x, fall.above), fall.probe);
      float cellOut = max(min(cellSpan.y, fall.exit), fall.probe);
      samples += 1;
      vec4 depths = RELIEF_CELL_DEPTHS(cell);
      float crossing = reliefCellIntersection(grid, cell, depths, cellIn, cellOut);
      if (crossing >= 0.0f)
      {
        vec2 gapIn = reliefPatchGap(grid, cell, depths, cellIn);
        bool bracketed = crossing <= cellIn && cellIn > fall.above && gapIn.x < 0.0f;
        tHit = bracketed ? cellIn : crossing;
        bracketStart = bracketed ? fall.above : -1.0f;
        bracketGapAbove = fall.gapAbove;
        bracketGapBelow = gapIn;
        bracketRates = fall.rates;
        break;
      }
      fall.above = cellOut;
      fall.gapAbove = reliefPatchGap(grid, cell, depths, cellOut);
      fall.gapAbove.x = max(fall.gapAbove.x, 1e-30f);
      float bound = fall.gapAbove.x + fall.rates.x * (fall.exit - fall.above);
      // no crossing in the node: past it
      fall.searching = fall.above < fall.exit && bound <= 0.0f;
      passes = !fall.searching;
      passCell = fall.entryCell;
      passExit = fall.exit;
      passLow = max(bound, 0.0f);
      if (fall.searching)
      {
        // else Newton from above, where the rates allow a crossing (rates.x <= rates.y < 0
        // in a falling node); a bisection when two reads have not halved that span; the exit
        // where a bracket would end within endSpan
        float soonest = fall.above - fall.gapAbove.x / fall.rates.x;
        float latest = min(fall.above - fall.gapAbove.x / fall.rates.y, fall.exit);
        float estimate =
          fall.gapAbove.y < 0.0f ? fall.above - fall.gapAbove.x / fall.gapAbove.y : latest;
        float width = latest - fall.above;
        estimate = width > 0.5f * fall.olderWidth ? 0.5f * (soonest + latest) : estimate;
        fall.olderWidth = fall.lastWidth;
        fall.lastWidth = width;
        fall.probe = fall.exit - fall.above <= endSpan ? fall.exit
                                                       : min(max(estimate, soonest), latest);
        fall.probeLow = fall.low;
        fall.probeHigh = fall.high;
      }
    }
    if (passes)
    {
      // past the node, and up a level when the next node has another parent
      level = reliefSlopeLevelPast(grid, signs, inverseRun, passCell, passExit, level, size);
      t = passExit;
      gapLow = passLow;
    }
  }
  if (bracketStart >= 0.0f)
  {
    return reliefSlopeRefine(ray, grid, bracketStart, tHit, bracketGapAbove, bracketGapBelow,
      bracketRates, samples, endSpan);
  }
  return tHit >= 0.0f ? reliefGridHit(ray, grid, tHit, true, samples)
                      : reliefGridEnd(ray, grid, samples);
}

ReliefHit reliefSearchSlopeMipmap(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefSlopeMipmapWithin(ray, 0.0f);
}
