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
//      the top of the child at the exit, or else one read of the cell there, says whether,
//      and a crossing is bracketed there;
// otherwise down a level, where the ray reaches the node's top. A node's texel also holds its
// children's tops: while it is in hand, a child the ray clears (by its top, or by the parent's
// Lipschitz bound) is passed over without a read, so a read buys two levels' worth of tests.
// Single cells are solved as ExactDDA does. A bracket [above, below] holding one crossing is
// closed by reading cells where Newton's estimate or, with the gap and its rate known at both
// ends, a cubic Hermite interpolant's root puts it, within what the rates allow, each read
// solving the whole cell: with one crossing, the first zero of a cell entered above the field
// is it. Exact: every skip is proven, every hit solved from a point known above the field.
// Shared with the CPU mirror; see vtkReliefCommon.glsl for the rules. Needs
// vtkReliefGridSearch.glsl (its pyramid's levels) and vtkReliefSafetySearch.glsl
// (reliefCellAfter) before it, and RELIEF_SLOPE_NODE(node, level): vec4 (least depth, packed
// dD/dx bounds, packed dD/dy bounds, children's coded tops) of a node above level 0, unpacked
// by reliefSlopeDecode and reliefSlopeChildTops (the GPU's in vtkReliefGridSearch.glsl).

// One code of vtkSlopeMipmapFilter::EncodeSlopes: 2048 is 0, each code away from it one
// 128th of an octave from 2^-15.
float reliefSlopeValue(float code)
{
  float steps = code - 2048.0f;
  return steps == 0.0f ? 0.0f : sign(steps) * exp2(abs(steps) / 128.0f - 15.0f);
}

// Two slope bounds packed as low * 4096 + high (exact integers in a float).
vec2 reliefSlopeDecode(float codes)
{
  float low = floor(codes / 4096.0f);
  return vec2(reliefSlopeValue(low), reliefSlopeValue(codes - low * 4096.0f));
}

// The least depths of a node's four children (slot x + 2 y) from the node's own, `top`, and
// their codes (vtkSlopeMipmapFilter::EncodeChildTops): each at most the child's.
// Integer parts are taken by multiplying with exact powers of two, never dividing (a GPU's
// division may land just below an integer).
vec4 reliefSlopeChildTops(float top, float codes)
{
  float exponent = floor(codes * (1.0f / 1048576.0f));
  float rest = codes - exponent * 1048576.0f;
  float unit = 1.0f / float(1 << (int(exponent) + 4)); // within the encoder's margin
  vec4 tops;
  float higher = floor(rest * (1.0f / 32.0f));
  tops.x = top + (rest - 32.0f * higher) * unit;
  rest = floor(higher * (1.0f / 32.0f));
  tops.y = top + (higher - 32.0f * rest) * unit;
  higher = floor(rest * (1.0f / 32.0f));
  tops.z = top + (rest - 32.0f * higher) * unit;
  tops.w = top + higher * unit;
  return tops;
}

// A child's top from its node's children's tops (reliefSlopeChildTops): `slot` is the
// child's offset from the node's first child, more than 1 in the last node's folded third
// child (or where an axis of one node has a single child: its slot holds the node's own
// top). Selects, where a variable index into a vector may go through memory.
float reliefSlopeChildTop(vec4 tops, vec2 slot)
{
  return slot.y > 0.0f ? (slot.x > 0.0f ? tops.w : tops.z) : (slot.x > 0.0f ? tops.y : tops.x);
}

// The least and most rate of the gap along the ray (per unit of t) over a node whose
// gradients lie in the box of `node`.
vec2 reliefSlopeRates(vec4 node, ReliefGridRay grid)
{
  vec2 x = reliefSlopeDecode(node.y) * grid.direction.x;
  vec2 y = reliefSlopeDecode(node.z) * grid.direction.y;
  return vec2(min(x.x, x.y) + min(y.x, y.y) - grid.descent,
    max(x.x, x.y) + max(y.x, y.y) - grid.descent);
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

// The crossing in [above, below], where the gap falls all along (at a rate within
// `rates`, rates.y < 0), so there is one, and every point before it is above the field:
// gap and rate at `below` known (gapBelow, gap < 0). Each probe reads the cell where the
// Hermite interpolant (gap and rate known at both ends) or Newton (from below) puts the
// crossing, bounded by the rates, and solves it over its part of the bracket: the crossing,
// or a new end with its gap and rate known exactly; when two probes have not halved the
// bracket, a bisection follows. A bracket no longer than `endSpan` in t ends the search at
// its far end (the Automatic search's tolerance; 0: exact).
ReliefHit reliefSlopeRefine(ReliefRay ray, ReliefGridRay grid, float above, float below,
  vec2 gapBelow, vec2 rates, int samples, float endSpan)
{
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  vec2 ahead = vec2(max(signs.x, 0.0f), max(signs.y, 0.0f));
  vec2 gapAbove = vec2(-1.0f, 0.0f); // gap and rate at `above`, once a probe knows them
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
    // rounding may cross the bounds: then `high` (GLSL's clamp is undefined there)
    float probe = min(max(width > 0.5f * olderWidth ? 0.5f * (low + high) : estimate, low), high);
    olderWidth = lastWidth;
    lastWidth = width;
    vec2 cell = floor(reliefGridAt(grid, probe));
    vec2 behind = vec2(cell.x + 1.0f - ahead.x, cell.y + 1.0f - ahead.y);
    vec2 entries = reliefCrossings(grid, behind, signs, inverseRun);
    vec2 exits = reliefCrossings(grid, cell + ahead, signs, inverseRun);
    float tIn = min(max(max(entries.x, entries.y), above), probe);
    float tOut = max(min(min(exits.x, exits.y), below), probe);
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

// The crossing bracketed in [above, below], where `cell` (its corners read) holds the ray
// on or below the field at `below`: that cell first, back to where the ray entered it (no
// further read when it holds the crossing), then reliefSlopeRefine, ending as it does.
ReliefHit reliefSlopeBracket(ReliefRay ray, ReliefGridRay grid, float above, float below,
  vec2 cell, vec4 depths, vec2 rates, int samples, float endSpan)
{
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  vec2 ahead = vec2(max(signs.x, 0.0f), max(signs.y, 0.0f));
  vec2 behind = vec2(cell.x + 1.0f - ahead.x, cell.y + 1.0f - ahead.y);
  vec2 entries = reliefCrossings(grid, behind, signs, inverseRun);
  float tIn = min(max(max(entries.x, entries.y), above), below);
  float back = reliefCellIntersection(grid, cell, depths, tIn, below);
  vec2 gap = reliefPatchGap(grid, cell, depths, tIn);
  // no crossing in the cell (the exit's gap was 0 within rounding), or one inside it, or
  // the bracket all in it: the hit is found
  if (back < 0.0f || back > tIn || tIn <= above || gap.x >= 0.0f)
  {
    return reliefGridHit(ray, grid, back >= 0.0f ? back : below, true, samples);
  }
  return reliefSlopeRefine(ray, grid, above, tIn, gap, rates, samples, endSpan);
}

// The search; a bracket no longer than `endSpan` in t ends it at its far end (0: exact).
ReliefHit reliefSlopeMipmapWithin(ReliefRay ray, float endSpan)
{
  vec2 size = RELIEF_DEPTH_SIZE;
  ReliefGridRay grid = reliefGridRay(ray, size);
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  // start two levels below the one whose nodes span the ray's whole run: the slopes
  // prove more in smaller nodes, and climbing is cheap
  int level = clamp(reliefPyramidRunLevel(grid) - 2, 0, RELIEF_PYRAMID_TOP);
  float t = 0.0f;
  float gapLow = 0.0f; // a lower bound of the gap at t
  int samples = 0;
  // the texel in hand: its node, level (-1: none) and tile, its children's tops and rates
  vec2 heldNode = vec2(0.0f, 0.0f);
  int heldLevel = -1;
  vec2 heldOrigin = vec2(0.0f, 0.0f);
  vec4 heldTops = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  vec2 heldRates = vec2(0.0f, 0.0f);
  // the outcome, acted on after the loop so that the loop body stays small (every fragment
  // of a SIMD group runs through all of it): a hit at tHit, or a crossing bracketed in
  // [bracketStart, tHit] by the cell at tHit (its corners read), in a node of `rates`
  float tHit = -1.0f;
  float bracketStart = -1.0f;
  vec2 bracketCell = vec2(0.0f, 0.0f);
  vec4 bracketDepths = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  vec2 bracketRates = vec2(0.0f, 0.0f);
  for (int i = 0; i < RELIEF_MAX_ITERATIONS && t < 1.0f; ++i)
  {
    vec2 cell = reliefCellAfter(grid, t, signs, inverseRun);
    vec2 tile = floor(vec2(cell.x / size.x, cell.y / size.y));
    vec2 origin = vec2(tile.x * size.x, tile.y * size.y);
    float span = float(1 << level); // exact, unlike exp2 on some GPUs
    vec2 levelSize = reliefPyramidSize(level);
    vec2 node = min(floor((cell - origin) / span), vec2(levelSize.x - 1.0f, levelSize.y - 1.0f));
    vec2 low = origin + node * span;
    vec2 high = reliefPyramidNodeEnd(node, level, origin);
    vec2 exits = reliefBoxExits(grid, low, high, signs, inverseRun);
    float tOut = min(max(min(exits.x, exits.y), t), 1.0f);
    float zOut = grid.depth + tOut * grid.descent;
    bool over = false;
    float nextLow = 0.0f;
    if (level + 1 == heldLevel && origin == heldOrigin &&
      reliefPyramidParent(node, level) == heldNode)
    {
      // the parent's texel in hand: the node's top, and the parent's Lipschitz bound
      float top = reliefSlopeChildTop(heldTops, node - 2.0f * heldNode);
      float bound = gapLow + heldRates.x * (tOut - t);
      over = zOut < top || bound > 0.0f;
      nextLow = max(max(top - zOut, bound), 0.0f);
    }
    // what the step reads: at level 0 the cell itself (its corners hold all a node would);
    // above, the node's texel and, in case (d), the cell at the node's exit
    bool readsCell = !over && level == 0;
    vec2 readCell = cell;
    vec2 rates = vec2(0.0f, 0.0f);
    if (!over && level > 0)
    {
      samples += 1;
      vec4 texel = RELIEF_SLOPE_NODE(node, level);
      rates = reliefSlopeRates(texel, grid);
      float bound = gapLow + rates.x * (tOut - t); // the gap at the exit is at least this
      over = zOut < texel.x || rates.x >= 0.0f || bound > 0.0f;
      nextLow = max(max(texel.x - zOut, bound), 0.0f);
      // the children's tops, needed only where the ray goes on into the node
      vec4 tops = over ? vec4(0.0f, 0.0f, 0.0f, 0.0f) : reliefSlopeChildTops(texel.x, texel.w);
      if (!over && rates.y < 0.0f)
      {
        // (d): a gap that only falls and is still open at the exit was open all along:
        // the exit's child says so when the ray clears its top there, else the exit's
        // cell, the node's whatever side of the border rounding puts the exit
        readCell = min(max(floor(reliefGridAt(grid, tOut)), low), high - 1.0f);
        float exitTop = reliefSlopeChildTop(tops, floor((readCell - low) / (0.5f * span)));
        over = zOut < exitTop;
        nextLow = max(exitTop - zOut, nextLow);
        readsCell = !over;
      }
      if (!over && !readsCell)
      {
        // down, where the ray reaches the node's top, the gap bound carried there, with
        // the node's texel in hand for its children (a texel passed over stays out of
        // hand, so that its parent's still serves its siblings)
        heldNode = node;
        heldLevel = level;
        heldOrigin = origin;
        heldTops = tops;
        heldRates = rates;
        float tDown = max(t, min((texel.x - grid.depth) / grid.descent, tOut));
        gapLow = max(gapLow + rates.x * (tDown - t), 0.0f);
        t = tDown;
        level -= 1;
        continue;
      }
    }
    if (readsCell)
    {
      samples += 1;
      vec4 depths = RELIEF_CELL_DEPTHS(readCell);
      float gapOut = reliefPatchGap(grid, readCell, depths, tOut).x;
      // a cell is solved from t; in (d) a gap closed at the exit brackets the one crossing
      tHit = level == 0 ? reliefCellIntersection(grid, cell, depths, t, tOut)
                        : (gapOut <= 0.0f ? tOut : -1.0f);
      if (tHit >= 0.0f)
      {
        bracketStart = level == 0 ? -1.0f : t;
        bracketCell = readCell;
        bracketDepths = depths;
        bracketRates = rates;
        break;
      }
      over = true;
      nextLow = max(gapOut, 0.0f);
    }
    // past the node, and up a level when the next node has another parent
    vec2 next = reliefCellAfter(grid, tOut, signs, inverseRun);
    float parentSpan = 2.0f * span;
    bool climbs = floor(next.x / size.x) != tile.x || floor(next.y / size.y) != tile.y ||
      floor((next.x - origin.x) / parentSpan) != floor((cell.x - origin.x) / parentSpan) ||
      floor((next.y - origin.y) / parentSpan) != floor((cell.y - origin.y) / parentSpan);
    level = climbs ? min(level + 1, RELIEF_PYRAMID_TOP) : level;
    t = tOut;
    gapLow = nextLow;
  }
  if (bracketStart >= 0.0f)
  {
    return reliefSlopeBracket(ray, grid, bracketStart, tHit, bracketCell, bracketDepths,
      bracketRates, samples, endSpan);
  }
  return tHit >= 0.0f ? reliefGridHit(ray, grid, tHit, true, samples)
                      : reliefGridEnd(ray, grid, samples);
}

ReliefHit reliefSearchSlopeMipmap(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefSlopeMipmapWithin(ray, 0.0f);
}
