// vtkRelief: the fixed-step searches (Linear, LinearBinary, Secant) and the self-shadow
// query. They sample the filtered field at evenly spaced ray points, so features
// narrower than a step can be missed. One result for every search (ReliefHit); the
// first t in [0, 1] where the ray is on or below the field.
// Shared with the CPU mirror; see vtkReliefCommon.glsl for the rules.

struct ReliefBracket
{
  float above;     // last parameter known above the field
  float below;     // first parameter found on or below it
  float aboveGap;  // field depth minus ray depth at above (> 0; -1 when not sampled)
  float belowGap;  // the same at below (<= 0)
  bool found;
  int samples;
};

// Field depth minus ray depth: positive while the ray is above the field.
float reliefGap(vec3 point)
{
  return RELIEF_DEPTH(vec2(point.x, point.y)) - point.z;
}

// Fixed-step linear search (Policarpo et al. 2005): the first of `steps` equally
// spaced samples that is below the field. Thin features narrower than a step are missed.
ReliefBracket reliefLinearBracket(ReliefRay ray, int steps)
{
  ReliefBracket bracket;
  bracket.above = 0.0f;
  bracket.below = 1.0f;
  bracket.aboveGap = -1.0f;
  bracket.belowGap = 0.0f;
  bracket.found = false;
  bracket.samples = 0;
  float dt = 1.0f / float(steps);
  for (int i = 1; i <= steps; ++i)
  {
    float t = float(i) * dt;
    float gap = reliefGap(reliefRayAt(ray, t));
    bracket.samples += 1;
    if (gap <= 0.0f)
    {
      bracket.below = t;
      bracket.belowGap = gap;
      bracket.found = true;
      break;
    }
    bracket.above = t;
    bracket.aboveGap = gap;
  }
  return bracket;
}

ReliefHit reliefHitAt(ReliefRay ray, float t, float above, bool found, int samples)
{
  ReliefHit result;
  result.t = t;
  result.position = reliefRayAt(ray, t);
  result.clear = reliefRayAt(ray, above);
  result.hit = found;
  result.samples = samples;
  return result;
}

// Linear search alone: the hit is the first sample below the field.
ReliefHit reliefSearchLinear(ReliefRay ray, int linearSteps, int refinementSteps)
{
  ReliefBracket bracket = reliefLinearBracket(ray, linearSteps);
  return reliefHitAt(ray, bracket.below, bracket.above, bracket.found, bracket.samples);
}

// Bisection inside a bracket: halves the interval `steps` times and returns its middle.
ReliefHit reliefBinaryRefine(ReliefRay ray, ReliefBracket bracket, int steps)
{
  float above = bracket.above;
  float below = bracket.below;
  int samples = bracket.samples;
  for (int i = 0; i < steps; ++i)
  {
    float middle = 0.5f * (above + below);
    samples += 1;
    if (reliefBelowField(reliefRayAt(ray, middle)))
    {
      below = middle;
    }
    else
    {
      above = middle;
    }
  }
  return reliefHitAt(ray, 0.5f * (above + below), above, bracket.found, samples);
}

// Linear then binary search (Policarpo et al. 2005; 10 + 5 steps by default).
ReliefHit reliefSearchLinearBinary(ReliefRay ray, int linearSteps, int refinementSteps)
{
  ReliefBracket bracket = reliefLinearBracket(ray, linearSteps);
  if (!bracket.found)
  {
    return reliefHitAt(ray, 1.0f, bracket.above, false, bracket.samples);
  }
  return reliefBinaryRefine(ray, bracket, refinementSteps);
}

// Linear then secant search (parallax occlusion mapping, Tatarchuk 2006): the crossing
// is taken where the straight line through the bracket's two gaps meets zero. Each of
// `refinementSteps` further samples at that point shrinks the bracket (regula falsi, with
// the Illinois halving so one end cannot stall); 0 of them is POM exactly.
ReliefHit reliefSearchSecant(ReliefRay ray, int linearSteps, int refinementSteps)
{
  ReliefBracket bracket = reliefLinearBracket(ray, linearSteps);
  if (!bracket.found)
  {
    return reliefHitAt(ray, 1.0f, bracket.above, false, bracket.samples);
  }
  if (bracket.aboveGap < 0.0f)
  {
    bracket.aboveGap = max(reliefGap(reliefRayAt(ray, bracket.above)), 0.0f);
    bracket.samples += 1;
  }
  float above = bracket.above;
  float below = bracket.below;
  float aboveGap = bracket.aboveGap;
  float belowGap = bracket.belowGap;
  int samples = bracket.samples;
  int keptSide = 0; // +1: above was kept last time, -1: below
  for (int i = 0; i < refinementSteps; ++i)
  {
    float t = above + (below - above) * aboveGap / max(aboveGap - belowGap, 1e-30f);
    float gap = reliefGap(reliefRayAt(ray, t));
    samples += 1;
    if (gap <= 0.0f)
    {
      below = t;
      belowGap = gap;
      aboveGap = keptSide == 1 ? 0.5f * aboveGap : aboveGap;
      keptSide = 1;
    }
    else
    {
      above = t;
      aboveGap = gap;
      belowGap = keptSide == -1 ? 0.5f * belowGap : belowGap;
      keptSide = -1;
    }
  }
  float t = above + (below - above) * aboveGap / max(aboveGap - belowGap, 1e-30f);
  return reliefHitAt(ray, t, above, true, samples);
}

// Self-shadowing: is the hit lit by a light in texture-space direction lightDirection?
// The light ray is searched from where it enters the relief down to the hit's clear
// point, the last point the view search found above the field: meeting the field on
// the way means the light is blocked. (Aiming at the hit itself, which the search puts
// on or just below the surface, would let the surface shadow itself.)
float reliefLightVisibility(vec3 clearPoint, vec3 lightDirection, int steps)
{
  if (lightDirection.z >= 0.0f)
  {
    return 0.0f; // the light is below the surface plane
  }
  if (clearPoint.z <= 0.0f)
  {
    return 1.0f; // nothing of the relief rises above its top
  }
  ReliefBracket bracket = reliefLinearBracket(reliefLightRay(clearPoint, lightDirection), steps);
  return bracket.found ? 0.0f : 1.0f;
}
