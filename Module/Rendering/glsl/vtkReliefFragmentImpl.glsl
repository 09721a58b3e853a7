  // frame: the fragment's view ray in relief texture space (vtkReliefCommon.glsl's frame
  // interface, implemented by the mapper's frame file)
  // texture coordinates that are not finite (a broken mesh) hold no mapping: the fragment
  // is shaded plainly, its texture read at the origin
  bool reliefEntryUsable =
    !any(isnan(reliefTCoordVSOutput)) && !any(isinf(reliefTCoordVSOutput));
  vec2 reliefEntryTCoord = reliefEntryUsable ? reliefTCoordVSOutput : vec2(0.0);
  reliefGradX = dFdx(reliefEntryTCoord);
  reliefGradY = dFdy(reliefEntryTCoord);
  ReliefFragment reliefFragment;
  reliefFragment.viewVC =
    cameraParallel == 1 ? vec3(0.0, 0.0, -1.0) : normalize(reliefPositionVSOutput);
  reliefFragment.tcoord = reliefEntryTCoord;
  reliefFragment.tcoordAlongX = reliefGradX;
  reliefFragment.tcoordAlongY = reliefGradY;
  reliefFragment.positionAlongX = dFdx(reliefPositionVSOutput);
  reliefFragment.positionAlongY = dFdy(reliefPositionVSOutput);
  // the side the mesh's winding faces: a mirroring actor matrix turns the screen's round
  reliefFragment.frontFacing = gl_FrontFacing == (reliefMirrored == 0);
  reliefFragment.twoSided = reliefTwoSided == 1;
  reliefFragment.depthScale = reliefDepthScale;
  reliefFragment.deepest = RELIEF_DEEPEST;
  reliefFragment.eyeDistance = cameraParallel == 1 ? 1e30 : length(reliefPositionVSOutput);
  ReliefFrame reliefFrame = reliefFrameOf(reliefFragment);
  // texture coordinates that map no area here (the triangle's points share one (u, v) or
  // lie on a line) give the relief no direction, and its rays would run without end: the
  // fragment is shaded plainly (vtkReliefSurfaceFilter warns, testing the triangle's
  // corners alike)
  float reliefTCoordArea = abs(reliefGradX.x * reliefGradY.y - reliefGradX.y * reliefGradY.x);
  bool reliefMapsArea = reliefTCoordArea >
    1e-6 * max(dot(reliefGradX, reliefGradX), dot(reliefGradY, reliefGradY));
  bool reliefFrameUsable = reliefEntryUsable && reliefMapsArea && reliefFrame.usable;
  reliefAxisU = reliefFrame.axisU;
  reliefAxisV = reliefFrame.axisV;
  reliefFrameN = reliefFrame.normal;
  vec3 reliefViewVC = reliefFragment.viewVC;

  // search; the hit's distance along the view ray (world units), and the tilt of the
  // reference surface there in view space (none for flat frames)
  float reliefHitDistance = 0.0;
  vec3 reliefSurfaceSlope = vec3(0.0);
  if (reliefDepthScale > 0.0 && reliefFrameUsable)
  {
    if (reliefFrameHides(reliefFrame, reliefFragment))
    {
      discard;
    }
    ReliefRay reliefViewRayTS = reliefScreenViewRay(reliefFrame, reliefFragment);
    reliefViewHit = RELIEF_SEARCH(reliefViewRayTS, reliefLinearSteps, reliefBinarySteps);
    if (reliefFrameRayLeft(reliefFrame, reliefViewRayTS, reliefViewHit))
    {
      discard;
    }
    reliefHitDistance =
      reliefFrameHitDistance(reliefFrame, reliefFragment, reliefViewRayTS, reliefViewHit);
    reliefSurfaceSlope = reliefFrameSurfaceSlope(reliefFrame, reliefFragment, reliefHitDistance);
  }
  else
  {
    reliefViewHit.position = vec3(reliefEntryTCoord, 0.0);
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
  reliefHitTCoord -= round(reliefHitTCoord - reliefEntryTCoord);
  vec3 reliefHitVC = reliefPositionVSOutput + reliefViewVC * reliefHitDistance;
  // lit as the pixel's footprint is
  vec3 reliefLitNormalVC = normalize(reliefFrameN + reliefSurfaceSlope);
  if (reliefFrameUsable)
  {
    reliefLitNormalVC = reliefShadeFootprint(
      reliefFrame, reliefFragment, reliefHitTCoord, reliefSurfaceSlope, reliefViewHit.samples);
  }
  else
  {
    reliefFootprintCount = 0;
    reliefAddFootprintNormal(reliefLitNormalVC, 1.0);
  }
  vec4 reliefHitDC = reliefVCDCMatrix * vec4(reliefHitVC, 1.0);
  float reliefFragDepth = reliefDepthCorrection == 1 ?
    clamp(0.5 * reliefHitDC.z / reliefHitDC.w + 0.5, 0.0, 1.0) : gl_FragCoord.z;
