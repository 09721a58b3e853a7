// vtkRelief: SafetyRadius and RobustBinary, the robust binary search of Baboud and Decoret 2006,
// s3.4. Cell c stores a radius n (vtkSafetyRadiusFilter): a ray on or above the field at a point
// over c, once more than e below the field, is nowhere above it again before it leaves the square
// of cells within n of c. So the search jumps from square exit to square exit while the ray stays
// above. An exit found below brackets a crossing (the only one when e = 0): bisection, reading the
// exact patch, narrows the bracket to a few cells and an exact cell walk finishes it.
// Radius 0 promises nothing (Baboud and Decoret 2006, Fig. 7). The two searches differ there:
// - SafetyRadius intersects that cell exactly and goes on from its exit. With e = 0 the hit is
//   exact; with e > 0 the search steps over the ray only where it is at most e below the field,
//   so it returns a true hit, at or after the first one and no later than where the ray is first
//   more than e below the field.
// - RobustBinary follows the paper as written: the radius is clamped to the cell itself, tested
//   at its exit only, so a ray that dips into a radius-0 cell and out again within it is missed
//   too (errors at silhouettes, which e bounds only where radii are not 0).
// Shared with the CPU mirror; see vtkReliefCommon.glsl for the rules. Needs
// RELIEF_SAFETY_RADIUS(cell): the radius of a cell (unwrapped index; the includer repeats it), in
// cells.

#ifndef RELIEF_SAFETY_RADIUS
// The GPU's radii, one texel per cell: read at the texel's centre with nearest filtering,
// so that the sampler repeats the index (cheaper than texelFetch of mod(cell, size));
// cells as far as 10^5 texels away still land within 0.01 texel.
// (vec4(): the shader also compiles where another method's image is read as integers)
#define RELIEF_SAFETY_RADIUS(cell) \
  vec4(textureLod(reliefAccelerationTexture, ((cell) + 0.5) / reliefTextureSize, 0.0)).r
#endif

// The cell the ray enters at t: on a cell border the one ahead, so a jump that ends on
// a square's side starts the next square beyond it, and the search always advances.
vec2 reliefCellAfter(ReliefGridRay grid, float t, vec2 signs, vec2 inverseRun)
{
  vec2 at = reliefGridAt(grid, t);
  vec2 cell = vec2(signs.x > 0.0f ? floor(at.x) : ceil(at.x) - 1.0f,
    signs.y > 0.0f ? floor(at.y) : ceil(at.y) - 1.0f);
  // rounding can leave `at` short of a border the ray has already crossed at t
  vec2 exits = reliefCrossings(
    grid, vec2(cell.x + max(signs.x, 0.0f), cell.y + max(signs.y, 0.0f)), signs, inverseRun);
  cell.x += exits.x <= t ? signs.x : 0.0f;
  cell.y += exits.y <= t ? signs.y : 0.0f;
  return cell;
}

// The jumps of both searches; `clampsZeroRadius` selects RobustBinary's clamp (see above).
ReliefHit reliefSafetyRadiusJumps(ReliefRay ray, bool clampsZeroRadius)
{
  ReliefGridRay grid = reliefGridRay(ray, RELIEF_DEPTH_SIZE);
  vec2 signs = reliefStepSigns(grid);
  vec2 inverseRun = reliefInverseRun(grid);
  float t = 0.0f;
  int samples = 0;
  // the outcome, acted on after the loop so that the loop body stays small: a hit at
  // tHit, found exactly, or bracketed in [bracketStart, tHit]
  float tHit = -1.0f;
  float bracketStart = -1.0f;
  for (int i = 0; i < RELIEF_MAX_ITERATIONS && t < 1.0f; ++i)
  {
    vec2 cell = reliefCellAfter(grid, t, signs, inverseRun);
    float radius = RELIEF_SAFETY_RADIUS(cell);
    samples += 1;
    vec2 square = vec2(signs.x > 0.0f ? cell.x + radius + 1.0f : cell.x - radius,
      signs.y > 0.0f ? cell.y + radius + 1.0f : cell.y - radius);
    vec2 exits = reliefCrossings(grid, square, signs, inverseRun);
    float tExit = min(min(exits.x, exits.y), 1.0f);
    samples += 1;
    if (radius < 0.5f && !clampsZeroRadius)
    {
      tHit = reliefCellIntersection(grid, cell, RELIEF_CELL_DEPTHS(cell), t, tExit);
      if (tHit >= 0.0f)
      {
        break;
      }
    }
    else if (reliefCellGap(grid, tExit) <= 0.0f)
    {
      // the only crossing (e = 0) lies in [t, tExit]
      bracketStart = t;
      tHit = tExit;
      break;
    }
    t = tExit;
  }
  if (bracketStart >= 0.0f)
  {
    return reliefRefineCrossing(ray, grid, bracketStart, tHit, samples);
  }
  return tHit >= 0.0f ? reliefGridHit(ray, grid, tHit, true, samples)
                      : reliefGridEnd(ray, grid, samples);
}

ReliefHit reliefSearchSafetyRadius(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefSafetyRadiusJumps(ray, false);
}

// The bracket is refined by the exact bisection and walk, where the paper bisects a fixed
// number of times (its step count is not given): the hit then lies on the field.
ReliefHit reliefSearchRobustBinary(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefSafetyRadiusJumps(ray, true);
}
