  // the view ray, from the eye (from the view plane in parallel projection), clipped to
  // the near plane and to the box, in model coordinates
  vec3 reliefRayOriginVC = cameraParallel == 1 ? vec3(reliefImpostorVC.xy, 0.0) : vec3(0.0);
  vec3 reliefRayDirectionVC =
    cameraParallel == 1 ? vec3(0.0, 0.0, -1.0) : normalize(reliefImpostorVC.xyz);
  float reliefRayStart = reliefNearVC / max(-reliefRayDirectionVC.z, 1e-6);
  ReliefImpostorSegment reliefSegment = reliefImpostorClip(
    (reliefImpostorVCMC * vec4(reliefRayOriginVC, 1.0)).xyz,
    (reliefImpostorVCMC * vec4(reliefRayDirectionVC, 0.0)).xyz, reliefImpostorLow,
    reliefImpostorHigh, reliefRayStart);
  if (!reliefSegment.crosses)
  {
    discard;
  }
  // search: the first point every view holds
  ReliefImpostorHit reliefHit =
    reliefImpostorSearch(reliefSegment, reliefLinearSteps, reliefBinarySteps);
  if (!reliefHit.hit)
  {
    discard;
  }
  // shade: the captured colour and normal of the view that sees the hit most squarely,
  // read at the level of the pixel's footprint there; the true depth
  int reliefShadingView = reliefImpostorShadingView(reliefSegment, reliefHit);
  vec3 reliefHitMC = mix(reliefSegment.entry, reliefSegment.exit, reliefHit.share);
  vec3 reliefHitVC = (reliefImpostorMCVC * vec4(reliefHitMC, 1.0)).xyz;
  vec3 reliefHitUV = reliefImpostorProjected(
    reliefImpostorProjections[reliefShadingView] * vec4(reliefHitMC, 1.0));
  float reliefPixelSize = reliefPixelSpread *
    (cameraParallel == 1 ? 1.0 : length(reliefHitVC - reliefRayOriginVC));
  float reliefColourLevel = log2(max(reliefPixelSize * reliefColourTexelsPerUnit, 1.0));
  vec3 reliefHitTexel = vec3(reliefHitUV.xy, float(reliefShadingView));
  vec4 reliefHitColour = textureLod(reliefImpostorColours, reliefHitTexel, reliefColourLevel);
  vec3 reliefLitNormalVC = reliefImpostorNormalMatrix *
    (mat3(reliefImpostorNormalFrames[reliefShadingView]) * reliefImpostorOctahedralNormal(
      textureLod(reliefImpostorNormals, reliefHitTexel, reliefColourLevel).xy));
  // a surface seen from behind is lit on the side seen
  reliefLitNormalVC = dot(reliefLitNormalVC, reliefLitNormalVC) > 1e-12 ?
    normalize(reliefLitNormalVC) : -reliefRayDirectionVC;
  reliefLitNormalVC = dot(reliefLitNormalVC, reliefRayDirectionVC) > 0.0 ?
    -reliefLitNormalVC : reliefLitNormalVC;
  vec4 reliefHitDC = reliefVCDCMatrix * vec4(reliefHitVC, 1.0);
  float reliefFragDepth = clamp(0.5 * reliefHitDC.z / reliefHitDC.w + 0.5, 0.0, 1.0);
  reliefFragCoordZ = reliefFragDepth;
  reliefFragCoordW = 1.0 / reliefHitDC.w;
