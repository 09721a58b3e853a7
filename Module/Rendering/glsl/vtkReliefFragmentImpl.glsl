  // frame: the fragment's view ray in relief texture space (seed 000 s3.4)
  reliefGradX = dFdx(reliefTCoordVSOutput);
  reliefGradY = dFdy(reliefTCoordVSOutput);
  reliefLod = reliefLevel(reliefTextureSize);
  reliefFrameN = normalize(reliefNormalVSOutput);
  reliefFrameT = normalize(
    reliefTangentVSOutput - reliefFrameN * dot(reliefFrameN, reliefTangentVSOutput));
  reliefFrameB = cross(reliefFrameN, reliefFrameT);
  // seen from behind, the relief is carved into the back: the normal turns, the
  // texture axes stay
  if (gl_FrontFacing == false) { reliefFrameN = -reliefFrameN; }
  reliefScale = reliefTextureScaleVSOutput;
  if (abs(reliefScale.x) < 1e-20) { reliefScale.x = 1e-20; }
  if (abs(reliefScale.y) < 1e-20) { reliefScale.y = 1e-20; }
  vec3 reliefViewVC =
    cameraParallel == 1 ? vec3(0.0, 0.0, -1.0) : normalize(reliefPositionVSOutput);

  // search; the hit's distance along the view ray (world units), and the tilt of the
  // reference surface there (the quadric's slope; none for the flat frame)
  float reliefHitDistance = 0.0;
  vec2 reliefSurfaceSlope = vec2(0.0);
  if (reliefDepthScale > 0.0)
  {
#ifdef RELIEF_QUADRIC
    // the curved frame (seed 000 s3.1-3.4): the view ray bends below the quadric; a ray
    // that comes back out of it without meeting the relief is past the silhouette
    vec3 reliefViewTF = vec3(dot(reliefViewVC, reliefFrameT), dot(reliefViewVC, reliefFrameB),
      dot(reliefViewVC, reliefFrameN));
    vec2 reliefQuadric = gl_FrontFacing ? reliefQuadricVSOutput : -reliefQuadricVSOutput;
    vec2 reliefTerms = reliefQuadricDepthTerms(reliefViewTF, reliefQuadric, reliefDepthScale);
    float reliefRange = reliefQuadricRange(reliefTerms);
    ReliefRay reliefViewRayTS = reliefQuadricViewRay(
      reliefTCoordVSOutput, reliefViewTF, reliefScale, reliefTerms, reliefRange);
#ifdef RELIEF_EXACT_DISTANCE
    reliefViewRayTS = reliefQuadricExact(
      reliefViewRayTS, reliefViewTF, reliefQuadric, reliefDepthScale, reliefRange);
#endif
    reliefViewHit = reliefSearch(reliefViewRayTS, reliefLinearSteps, reliefBinarySteps);
    if (!reliefViewHit.hit && reliefQuadricLeaves(reliefViewRayTS))
    {
      discard;
    }
    reliefHitDistance = reliefViewHit.t * reliefRange;
    reliefSurfaceSlope = -2.0 * reliefQuadric * reliefViewTF.xy * reliefHitDistance;
#else
    ReliefRay reliefViewRayTS =
      reliefViewRay(reliefTCoordVSOutput, reliefToTexture(reliefViewVC));
    reliefViewHit = reliefSearch(reliefViewRayTS, reliefLinearSteps, reliefBinarySteps);
    reliefHitDistance = reliefViewHit.position.z * reliefDepthScale /
      max(-dot(reliefViewVC, reliefFrameN), 1e-6);
#endif
  }
  else
  {
    reliefViewHit.position = vec3(reliefTCoordVSOutput, 0.0);
    reliefViewHit.clear = reliefViewHit.position;
    reliefViewHit.t = 0.0;
    reliefViewHit.hit = true;
    reliefViewHit.samples = 0;
  }

  // shade: hit point, relief normal rebuilt with the live scales, true depth
  vec2 reliefHitTCoord = reliefViewHit.position.xy;
  // Textures repeat with period 1: bring the hit back within half a tile of the entry
  // (Mesa's llvmpipe stalls on mipmapped 8-bit reads far from it; grazing rays run far).
  // A colour texture that does not repeat reads right wherever the hit stays that close.
  reliefHitTCoord -= round(reliefHitTCoord - reliefTCoordVSOutput);
  vec3 reliefHitVC = reliefPositionVSOutput + reliefViewVC * reliefHitDistance;
  vec2 reliefSlope =
    reliefDepthGradient(reliefHitTCoord) * max(reliefDepthScale, 0.0) / reliefScale;
  vec3 reliefNormalTS = normalize(vec3(reliefSlope + reliefSurfaceSlope, 1.0));
  vec3 reliefLitNormalVC = normalize(reliefFrameT * reliefNormalTS.x +
    reliefFrameB * reliefNormalTS.y + reliefFrameN * reliefNormalTS.z);
  vec4 reliefHitDC = reliefVCDCMatrix * vec4(reliefHitVC, 1.0);
  float reliefFragDepth = reliefDepthCorrection == 1 ?
    clamp(0.5 * reliefHitDC.z / reliefHitDC.w + 0.5, 0.0, 1.0) : gl_FragCoord.z;
