// vtkRelief: the ConeStep search, relaxed cone stepping (Policarpo and Oliveira, GPU Gems
// 3 ch. 18) over the cone map of vtkConeStepMapFilter, whose cones hold for the bilinear
// field (see that class for the definition and the proof). Shared with the CPU mirror;
// see vtkReliefCommon.glsl for the rules. Needs vtkReliefSearch.glsl and
// vtkReliefGridSearch.glsl, and RELIEF_CONE_STEP(cell): vec2 (top depth, cone ratio in
// texels per unit depth) of a cell, its index unwrapped (the includer repeats it).
//
// Standing over a cell above its top, the ray may travel inside the cell's cone; it
// stays above the field there or enters it once. So each step goes to where the ray
// leaves the cone; a step that ends on or below the field brackets the first
// intersection, which bisection narrows and an exact walk over the last few cells
// finds. Where the cone would not carry the ray out of its cell (the ray below the
// cell's top, or the cone too narrow), the cell is intersected exactly instead, so the
// ray never crawls toward a surface it is about to meet.
//
// Bound: the hit is the first intersection with the bilinear field, exactly as
// ExactDDA's (up to float rounding). Bisection alone, without the walk, would place it
// within half the final bracket: a cone step over 2^(binarySteps + 1).

// Brackets of at most this many cells are walked exactly; longer ones are bisected first.
#define RELIEF_CONE_WALK_CELLS 4.0f

// Is the ray at t on or below the field? From the cell's four texels, exactly as the
// cell tests see the field: a filtered read may round the other way.
bool reliefConeBelow(ReliefGridRay grid, float t)
{
  vec2 at = reliefGridAt(grid, t);
  vec2 cell = floor(at);
  vec4 depths = RELIEF_CELL_DEPTHS(cell);
  float fx = at.x - cell.x;
  float fy = at.y - cell.y;
  float field = mix(mix(depths.x, depths.y, fx), mix(depths.z, depths.w, fx), fy);
  return grid.depth + t * grid.descent >= field;
}

// The first intersection inside [above, below], the ray above the field at `above`, on
// or below it at `below`, and entering it once between: bisect `binarySteps` times, on
// until the bracket spans at most RELIEF_CONE_WALK_CELLS cells, then walk it exactly.
ReliefHit reliefConeRefine(
  ReliefRay ray, ReliefGridRay grid, float above, float below, int binarySteps, int samples)
{
  float cellsPerT = max(abs(grid.direction.x), abs(grid.direction.y));
  for (int i = 0; i < RELIEF_MAX_ITERATIONS; ++i)
  {
    if (i >= binarySteps && (below - above) * cellsPerT <= RELIEF_CONE_WALK_CELLS)
    {
      break;
    }
    float middle = 0.5f * (above + below);
    samples += 1;
    if (reliefConeBelow(grid, middle))
    {
      below = middle;
    }
    else
    {
      above = middle;
    }
  }
  ReliefHit walk = reliefWalkCells(ray, grid, above, below, samples);
  // the walk rounds differently from the bisection only at a grazing touch
  return walk.hit ? walk : reliefGridHit(ray, grid, below, true, walk.samples);
}

ReliefHit reliefSearchConeStep(ReliefRay ray, int binarySteps)
{
  ReliefGridRay grid = reliefGridRay(ray, RELIEF_DEPTH_SIZE);
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  float run = length(grid.direction); // texels travelled per unit t
  vec2 cell = floor(grid.origin);
  float t = 0.0f;
  int samples = 0;
  for (int i = 0; i < RELIEF_MAX_ITERATIONS; ++i)
  {
    float depth = grid.depth + t * grid.descent;
    vec2 exits = reliefCrossings(
      grid, vec2(cell.x + max(signs.x, 0.0f), cell.y + max(signs.y, 0.0f)), signs, inverseRun);
    float tCell = min(exits.x, exits.y);
    vec2 cone = RELIEF_CONE_STEP(cell);
    samples += 1;
    // the ray leaves the cone where the distance it ran equals ratio * (top - depth)
    float tCone = t + cone.y * (cone.x - depth) / (run + cone.y * grid.descent);
    if (depth < cone.x && tCone > tCell)
    {
      float tNext = min(tCone, 1.0f);
      samples += 1;
      if (reliefConeBelow(grid, tNext))
      {
        return reliefConeRefine(ray, grid, t, tNext, binarySteps, samples);
      }
      if (tNext >= 1.0f)
      {
        break;
      }
      t = tNext;
      cell = floor(reliefGridAt(grid, t));
    }
    else
    {
      samples += 1;
      float tOut = min(tCell, 1.0f);
      float tHit = reliefCellIntersection(grid, cell, RELIEF_CELL_DEPTHS(cell), t, max(tOut, t));
      if (tHit >= 0.0f)
      {
        return reliefGridHit(ray, grid, tHit, true, samples);
      }
      if (tCell >= 1.0f)
      {
        break;
      }
      // on to the next cell by the side the ray leaves through, so rounding at its
      // border cannot send the search back into this cell
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
  }
  return reliefGridHit(ray, grid, 1.0f, false, samples);
}
