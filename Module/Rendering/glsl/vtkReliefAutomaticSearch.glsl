// vtkRelief: the Automatic search, the mapper's default: per fragment, the least work
// that keeps the hit within the screen tolerance (vtkOpenGLReliefMapper::ScreenTolerance,
// in pixels). The ray says how far its (u, v) run on screen (ReliefRay.screenRun, in
// tolerances: the view angle, DepthScale and the pixel's footprint in one number) and
// the height map's resolution says how many cells it crosses:
// - straight rays crossing a few cells: ExactDDA's walk, one sample a cell, exact;
// - a longer run within one tolerance: wherever the ray meets the field, the hit is
//   within the tolerance of the entry, so no search is needed; one secant step (parallax
//   occlusion mapping with a single interval, 3 samples) places it, and the shading is
//   normal mapping with parallax;
// - longer straight runs: ConeStep (or SlopeMipmap, reliefSearchAutomaticOverSlopes, where
//   the mapper's AutomaticAcceleration says so), whose steps grow with the run far more
//   slowly, ending where the bracket it found lies within the tolerance on screen and
//   within 1/20 of the depth; beyond 2048 cells, the curved rays' steps, whose cost is
//   bounded (they may pass features narrower than a step: the one place the regimes can
//   part by more than the tolerance). Where the run is not known (ScreenTolerance 0), exact;
// - curved rays (the quadric frame, reliefSearchAutomaticCurved): fixed steps of half a
//   texel, or of one tolerance where that is longer on screen, then bisection until the
//   bracket spans a quarter of the tolerance and 1/256 of the depth.
// The regimes meet where their hits lie within the tolerance of each other, so moving
// the camera across a boundary shifts the picture by less than the tolerance. Shared
// with the CPU mirror; needs vtkReliefSearch.glsl, vtkReliefGridSearch.glsl,
// vtkReliefSlopeSearch.glsl and vtkReliefConeSearch.glsl before it.

// Manhattan cells of the whole run up to which ExactDDA's walk, one sample a cell, costs
// less than ConeStep's cone reads, bisection and final cells (chosen on the automatic
// study's stones map, Documentation/results.md; kept, unmeasured, over SlopeMipmap, whose
// first steps on such runs are cell reads too), and less than the secant's three samples.
#define RELIEF_AUTOMATIC_WALK_CELLS 6.0f
#define RELIEF_AUTOMATIC_SECANT_CELLS 2.0f
// The most of the depth a bracket that ends the search may span: the written depth's
// bound, beside the tolerance on screen.
#define RELIEF_AUTOMATIC_DEPTH_SPAN 0.05f
// Manhattan cells beyond which a straight ray is stepped as a curved one is, in at most
// 256 steps, so that no fragment's cost is unbounded: on a real mesh whose rays ran
// thousands of cells (assimp's spider.obj, Data/README.md) ConeStep took 21 s a frame.
#define RELIEF_AUTOMATIC_CONE_CELLS 2048.0f
// Bounds of the curved search's fixed steps and halvings.
#define RELIEF_AUTOMATIC_MIN_STEPS 4.0f
#define RELIEF_AUTOMATIC_MAX_STEPS 256.0f

// The ray's (u, v) run from t = 0 to 1 in texels.
vec2 reliefRunTexels(ReliefRay ray)
{
  vec2 size = RELIEF_DEPTH_SIZE;
  return vec2(abs(ray.direction.x * size.x), abs(ray.direction.y * size.y));
}

// A ray whose whole run lies within the tolerance on screen: one secant step between its
// ends. Its depth is the secant's (not bounded), and where that step lands below the
// field the self-shadow starts at the entry, which lights the pixel.
ReliefHit reliefSearchWithinTolerance(ReliefRay ray)
{
  return reliefSearchSecant(ray, 1, 1);
}

ReliefHit reliefSearchAutomaticCurved(ReliefRay ray, int linearSteps, int refinementSteps)
{
  if (ray.screenRun <= 1.0f)
  {
    return reliefSearchWithinTolerance(ray);
  }
  // a step of half a texel, or of one tolerance where that is longer on screen
  float steps = clamp(ceil(min(2.0f * length(reliefRunTexels(ray)), ray.screenRun)),
    RELIEF_AUTOMATIC_MIN_STEPS, RELIEF_AUTOMATIC_MAX_STEPS);
  float halvings = ceil(log2(max(4.0f * ray.screenRun / steps, 256.0f / steps)));
  ReliefBracket bracket = reliefLinearBracket(ray, int(steps));
  if (!bracket.found)
  {
    return reliefHitAt(ray, 1.0f, bracket.above, false, bracket.samples);
  }
  return reliefBinaryRefine(ray, bracket, int(clamp(halvings, 1.0f, 16.0f)));
}

// Straight rays, long runs stepped over the slope pyramid (`overSlopes`) or the cone map.
ReliefHit reliefAutomaticStraight(ReliefRay ray, bool overSlopes)
{
  vec2 run = reliefRunTexels(ray);
  float cells = run.x + run.y;
  bool withinTolerance = ray.screenRun <= 1.0f;
  if (cells <= (withinTolerance ? RELIEF_AUTOMATIC_SECANT_CELLS : RELIEF_AUTOMATIC_WALK_CELLS))
  {
    return reliefSearchExactDDA(ray, 0, 0);
  }
  if (withinTolerance)
  {
    return reliefSearchWithinTolerance(ray);
  }
  if (cells > RELIEF_AUTOMATIC_CONE_CELLS && ray.screenRun < RELIEF_UNKNOWN_RUN)
  {
    return reliefSearchAutomaticCurved(ray, 0, 0); // bounded: at most 256 steps
  }
  float endSpan = min(1.0f / ray.screenRun, RELIEF_AUTOMATIC_DEPTH_SPAN);
  return overSlopes ? reliefSlopeMipmapWithin(ray, endSpan) : reliefConeStepWithin(ray, endSpan);
}

ReliefHit reliefSearchAutomatic(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefAutomaticStraight(ray, false);
}

ReliefHit reliefSearchAutomaticOverSlopes(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefAutomaticStraight(ray, true);
}
