// vtkRelief: path features cut into a relief-mapped base, beyond the path-feature paper
// (seed 004). Where no feature holds a point, the path search's matter is all that lies
// below the base plane (reliefPathCellTransition); here it is the height field hung from
// that plane, depth >= base + h(u, v), searched by one of the relief searches: the
// includer defines RELIEF_PATH_BASE_SEARCH as its function. The features stand on the
// plane as before: what they add above it is matter, what they cut is air, the field's
// matter too. So the solid is the features' solid over the flat base less the air
// between the plane and the field; its first point along a ray is found in turns: the
// features' walk finds where the ray first enters their solid, the field's search where
// it next reaches the field, and so on from there, until a point lies in both, or in
// what the features add above the plane. Straight rays only (the flat frames). Needs
// vtkReliefPathSearch.glsl and the relief searches, and reliefFieldGradient (the
// bilinear field's, vtkReliefGridSearch.glsl). Shared with the CPU mirror; see
// vtkReliefCommon.glsl for the rules.

// The most turns one ray takes: a groove crossed above the field takes two.
#define RELIEF_PATH_BASE_TURNS 8

// The relief search's ray from point t of a straight ray on: depth measured from the
// base plane, at the field's depth 1 at its t = 1, which is `span` of the ray's t.
ReliefRay reliefPathBaseRay(ReliefRay ray, float t, float base, float span)
{
  vec3 start = reliefRayAt(ray, t);
  ReliefRay below = ray;
  below.origin = vec3(start.x, start.y, start.z - base);
  below.direction = ray.direction * span;
  // (an unknown run stays unknown: it asks the Automatic search for an exact search)
  below.screenRun =
    ray.screenRun < RELIEF_UNKNOWN_RUN ? ray.screenRun * span : RELIEF_UNKNOWN_RUN;
  return below;
}

// The field's search along a straight ray from its point t on, down to the field's depth
// 1, as a hit of the ray itself (its t, its clear point).
ReliefHit reliefPathFieldFrom(
  ReliefRay ray, float t, float base, int linearSteps, int refinementSteps)
{
  float descent = max(ray.direction.z, 1e-30f);
  float span = (1.0f - (reliefRayAt(ray, t).z - base)) / descent;
  ReliefHit field = RELIEF_PATH_BASE_SEARCH(
    reliefPathBaseRay(ray, t, base, span), linearSteps, refinementSteps);
  float tClear = (field.clear.z + base - ray.origin.z) / descent;
  return reliefHitAt(ray, t + field.t * span, tClear, field.hit, field.samples);
}

// The first point of the solid along a straight ray from tStart to tEnd, or a miss at
// tEnd; where solidPastEnd, every point beyond tEnd is solid (it lies below the deepest
// cut). Sets what reliefPathWalk sets: reliefPathHitNormal, facing back along the ray
// (the field's where the hit lies on it), reliefPathHitMaterial (-1 there) and
// reliefPathNearest, over all its walks.
ReliefHit reliefPathOnReliefWalk(ReliefRay ray, float tStart, float tEnd, bool solidPastEnd,
  int linearSteps, int refinementSteps)
{
  float base = RELIEF_PATH_TEXEL(0).x;
  float t = tStart;
  bool onField = false; // t is where the field's search met the field
  bool found = false;
  float tHit = tEnd;
  float tClear = tEnd; // where the hit's shadow rays start: in air before it
  float tFieldClear = tStart; // the last field search's clear point
  bool fieldNormal = false; // the hit lies on the field: lit by its normal
  vec3 normal = vec3(0.0f, 0.0f, -1.0f);
  float material = -1.0f;
  int samples = 0;
  ReliefPathNearest nearest = reliefPathNoneNear();
  for (int turn = 0; turn < RELIEF_PATH_BASE_TURNS; ++turn)
  {
    // where the ray enters the features' solid from t on (t itself where it is in it)
    ReliefHit features = reliefPathWalk(ray, min(t, tEnd), tEnd, 0, vec2(0.0f, 0.0f), true);
    samples += features.samples;
    nearest = reliefPathNearer(nearest, reliefPathNearest.gap, reliefPathNearest.element,
      reliefPathNearest.joins, reliefPathNearest.near);
    nearest = reliefPathNearer(nearest, reliefPathNearest.second, -1, 0, reliefPathNearest.near);
    float tFeatures = t >= tEnd ? t : (features.hit ? features.t : tEnd);
    bool lost = !(t >= tEnd || features.hit || solidPastEnd); // a miss
    vec3 point = reliefRayAt(ray, tFeatures);
    float aboveField = base + RELIEF_DEPTH(vec2(point.x, point.y)) - point.z;
    // on the field where its search left the ray, unless a feature's surface lies between
    bool stayed = onField && tFeatures <= t + 1e-6f;
    // the walk met the base plane (its crossing may round to either side of it)
    bool plane = features.hit && abs(point.z - base) <= 1e-5f &&
      reliefPathHitNormal.x == 0.0f && reliefPathHitNormal.y == 0.0f;
    // in what a feature adds above the plane, or on a surface of the features within the
    // field (the plane there: the field's top, lit as the field)
    bool met = (point.z < base && !plane) || aboveField <= 0.0f;
    if (lost || stayed || met)
    {
      found = !lost;
      tHit = stayed ? t : tFeatures;
      // (a field search within the screen's tolerance stops below the field: its own
      // clear point, not one a fixed step back)
      tClear = stayed ? tFieldClear : (features.clear.z - ray.origin.z) / ray.direction.z;
      fieldNormal = stayed || plane;
      normal = reliefPathHitNormal;
      material = fieldNormal ? -1.0f : reliefPathHitMaterial;
      break;
    }
    // above the field: its search from there, down to its deepest
    ReliefHit field = reliefPathFieldFrom(ray, tFeatures, base, linearSteps, refinementSteps);
    samples += field.samples;
    t = field.t;
    tFieldClear = (field.clear.z - ray.origin.z) / ray.direction.z;
    onField = true;
    // a view ray ends on the field where its search or the turns run out (a grazing ray
    // rounds its end short of the field's floor); a light ray that reaches the point it
    // lights meets nothing
    found = solidPastEnd;
    tHit = t;
    tClear = tFieldClear;
    fieldNormal = true;
    material = -1.0f;
    if (!field.hit || (t > tEnd && !solidPastEnd))
    {
      break;
    }
  }
  vec3 hit = reliefRayAt(ray, tHit);
  vec2 gradient = reliefFieldGradient(vec2(hit.x, hit.y));
  normal = fieldNormal ? vec3(gradient.x, gradient.y, -1.0f) : normal;
  reliefPathNearest = nearest;
  reliefPathHitNormal = dot(normal, ray.direction) > 0.0f ? -normal : normal;
  reliefPathHitMaterial = material;
  return reliefHitAt(ray, found ? tHit : tEnd, found ? tClear : tEnd, found, samples);
}

// The field alone along a straight ray, where no feature comes near: its search from the
// ray's crossing of the base plane (the walk would find that crossing), lit as the field.
ReliefHit reliefPathBaseAlone(ReliefRay ray, int linearSteps, int refinementSteps)
{
  float base = RELIEF_PATH_TEXEL(0).x;
  float tPlane = max((base - ray.origin.z) / max(ray.direction.z, 1e-30f), 0.0f);
  ReliefHit field = reliefPathFieldFrom(ray, tPlane, base, linearSteps, refinementSteps);
  vec2 gradient = reliefFieldGradient(vec2(field.position.x, field.position.y));
  vec3 normal = vec3(gradient.x, gradient.y, -1.0f);
  reliefPathHitNormal = dot(normal, ray.direction) > 0.0f ? -normal : normal;
  reliefPathHitMaterial = -1.0f;
  return field;
}

// The search of the path features on the relief base: the view ray from the polygon down.
ReliefHit reliefSearchPathFeaturesOnRelief(ReliefRay ray, int linearSteps, int refinementSteps)
{
  return reliefPathOnReliefWalk(
    ray, 0.0f, reliefPathStraightEnd(ray), true, linearSteps, refinementSteps);
}

// Self-shadowing on the relief base: reliefPathLightVisibility's light ray, walked as the
// view ray is.
float reliefPathOnReliefLightVisibility(
  vec3 clearPoint, vec3 lightDirection, int linearSteps, int refinementSteps)
{
  if (lightDirection.z >= 0.0f)
  {
    return 0.0f;
  }
  if (clearPoint.z <= 0.0f)
  {
    return 1.0f;
  }
  vec3 hitNormal = reliefPathHitNormal;
  float hitMaterial = reliefPathHitMaterial;
  ReliefPathNearest hitNearest = reliefPathNearest;
  ReliefHit blocked = reliefPathOnReliefWalk(reliefLightRay(clearPoint, lightDirection), 0.0f,
    1.0f, false, linearSteps, refinementSteps);
  reliefPathHitNormal = hitNormal;
  reliefPathHitMaterial = hitMaterial;
  reliefPathNearest = hitNearest;
  return blocked.hit && blocked.t < 1.0f ? 0.0f : 1.0f;
}
