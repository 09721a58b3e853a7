// vtkRelief: the search the mapper chose, by the RELIEF_SEARCH_* define it compiled
// with (LinearBinary when none).
ReliefHit reliefSearch(ReliefRay ray, int linearSteps, int binarySteps)
{
#if defined(RELIEF_SEARCH_LINEAR)
  return reliefSearchLinear(ray, linearSteps);
#elif defined(RELIEF_SEARCH_SECANT)
  return reliefSearchSecant(ray, linearSteps, binarySteps);
#elif defined(RELIEF_SEARCH_EXACT_DDA)
  return reliefSearchExactDDA(ray);
#elif defined(RELIEF_SEARCH_SAFETY_RADIUS)
  return reliefSearchSafetyRadius(ray);
#elif defined(RELIEF_SEARCH_CONE_STEP)
  return reliefSearchConeStep(ray);
#elif defined(RELIEF_SEARCH_MAXIMUM_MIPMAP)
  return reliefSearchMaximumMipmap(ray);
#else
  return reliefSearchLinearBinary(ray, linearSteps, binarySteps);
#endif
}
