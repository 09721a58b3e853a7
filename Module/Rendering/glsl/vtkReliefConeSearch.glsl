// vtkRelief: the ConeStep search, relaxed cone stepping (Policarpo and Oliveira, GPU Gems
// 3 ch. 18) over the cone map of vtkConeStepMapFilter, whose cones hold for the bilinear
// field (see that class for the definition and the proof). Shared with the CPU mirror;
// see vtkReliefCommon.glsl for the rules. Needs vtkReliefSearch.glsl and
// vtkReliefGridSearch.glsl, and RELIEF_CONE_STEP(cell): vec2 (top depth, cone ratio in
// texels per unit depth) of a cell, its index unwrapped (the includer repeats it), which
// the includer reads from the 8-bit map through reliefConeDecode().
//
// Standing over a cell above its top, the ray may travel inside the cell's cone; it
// stays above the field there or enters it once. So each step goes to where the ray
// leaves the cone, or, where the cone would not carry it out of the cell, over the cell
// when the ray stays above the cell's top in it; both read only the cone map. A cell
// whose top the ray reaches is intersected exactly. If the step that led there ended on
// or below the field, it brackets the first intersection, which bisection narrows and
// an exact walk over the last few cells finds.
//
// Bound: the hit is the first intersection with the bilinear field, exactly as
// ExactDDA's (up to float rounding): the binary refinement only narrows the bracket
// that the exact walk finishes.

// A cell's (top, ratio) from vtkConeStepMapFilter::EncodeCone's two bytes, read as
// unsigned normalized values (code / 255); range: (the maximum ratio, the octaves below
// it that the ratio codes span).
vec2 reliefConeDecode(vec2 stored, vec2 range)
{
  float topCode = floor(stored.x * 255.0f + 0.5f);
  float ratioCode = floor(stored.y * 255.0f + 0.5f);
  float ratio =
    ratioCode < 0.5f ? 0.0f : range.x * exp2(range.y * (ratioCode - 255.0f) / 254.0f);
  return vec2(topCode * (1.0f / 255.0f), ratio);
}

#ifndef RELIEF_CONE_STEP
// The GPU's cone map, two bytes a cell, read as the radii are (vtkReliefSafetySearch.glsl).
uniform vec2 reliefConeRange; // vtkConeStepMapFilter's maximum ratio and RATIO_OCTAVES
#define RELIEF_CONE_STEP(cell) reliefConeDecode( \
  vec4(textureLod(reliefAccelerationTexture, ((cell) + 0.5) / reliefTextureSize, 0.0)).rg, \
  reliefConeRange)
#endif

// The search; a bracket no longer than `span` in t ends it at its far end (0: exact).
ReliefHit reliefConeStepWithin(ReliefRay ray, float span)
{
  ReliefGridRay grid = reliefGridRay(ray, RELIEF_DEPTH_SIZE);
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  float run = length(grid.direction); // texels travelled per unit t
  vec2 ahead = vec2(max(signs.x, 0.0f), max(signs.y, 0.0f));
  vec2 cell = floor(grid.origin);
  float t = 0.0f;
  float stepStart = -1.0f; // where the cone step that led to t began; -1: none did
  int samples = 0;
  // the outcome, acted on after the loop so that the loop body stays small (every
  // fragment of a SIMD group runs through all of it): a hit at tHit, found exactly, or
  // bracketed in [bracketStart, tHit]
  float tHit = -1.0f;
  float bracketStart = -1.0f;
  for (int i = 0; i < RELIEF_MAX_ITERATIONS; ++i)
  {
    // steps that read the cone map alone: along the cone while it carries the ray out of
    // its cell, or over a cell whose top the ray stays above. A loop of its own, so that
    // fragments processed together (SIMD lanes, GPU warps) step together and the exact
    // cell test below runs only when one of them needs it.
    bool toTheEnd = false;
    bool missed = false;
    vec2 exits = vec2(0.0f, 0.0f);
    float tCell = 0.0f;
    for (; i < RELIEF_MAX_ITERATIONS; ++i)
    {
      float depth = grid.depth + t * grid.descent;
      exits = reliefCrossings(grid, cell + ahead, signs, inverseRun);
      tCell = min(exits.x, exits.y);
      vec2 cone = RELIEF_CONE_STEP(cell);
      samples += 1;
      // the ray leaves the cone where the distance it ran equals ratio * (top - depth)
      float tCone = t + cone.y * (cone.x - depth) / (run + cone.y * grid.descent);
      // above the cell's top, so above the field: the step that led here crossed nothing
      bool above = depth < cone.x && tCell > t;
      bool alongCone = above && tCone > tCell;
      // or still above the top where the ray leaves the cell: nothing to meet in it
      bool overCell = above && !alongCone && grid.depth + tCell * grid.descent < cone.x;
      float tNext = alongCone ? tCone : tCell;
      if (!(alongCone || overCell) || tNext >= 1.0f)
      {
        toTheEnd = alongCone;
        missed = overCell;
        break;
      }
      // selected, not branched: fragments stepping either way run the same code
      vec2 across = exits.x < exits.y ? vec2(signs.x, 0.0f) : vec2(0.0f, signs.y);
      stepStart = alongCone ? t : -1.0f;
      cell = alongCone ? floor(reliefGridAt(grid, tNext)) : cell + across;
      t = tNext;
    }
    if (missed)
    {
      break;
    }
    if (toTheEnd)
    {
      samples += 1;
      if (reliefCellGap(grid, 1.0f) <= 0.0f)
      {
        bracketStart = t;
        tHit = 1.0f;
      }
      break;
    }
    // the ray reaches the cell's top inside the cell: the cell exactly
    samples += 1;
    float tOut = min(tCell, 1.0f);
    tHit = reliefCellIntersection(grid, cell, RELIEF_CELL_DEPTHS(cell), t, max(tOut, t));
    if (tHit >= 0.0f)
    {
      // on or below the field where a cone step ended: it entered the field once,
      // somewhere in that step
      bracketStart = tHit <= t ? stepStart : -1.0f;
      break;
    }
    if (tCell >= 1.0f)
    {
      break;
    }
    // on to the next cell by the side the ray leaves through, so rounding at its border
    // cannot send the search back into this cell
    stepStart = -1.0f;
    t = max(t, tCell);
    if (exits.x < exits.y)
    {
      cell.x += signs.x;
    }
    else
    {
      cell.y += signs.y;
    }
  }
  if (bracketStart >= 0.0f)
  {
    return reliefRefineCrossingWithin(ray, grid, bracketStart, tHit, samples, span);
  }
  return tHit >= 0.0f ? reliefGridHit(ray, grid, tHit, true, samples)
                      : reliefGridEnd(ray, grid, samples);
}

ReliefHit reliefSearchConeStep(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefConeStepWithin(ray, 0.0f);
}
