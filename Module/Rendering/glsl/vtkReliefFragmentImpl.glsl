  // frame: the fragment's view ray in relief texture space (seed 000 s3.4)
  // false where the frame holds no texture mapping: the fragment is shaded plainly, and
  // texture coordinates that are not finite (a broken mesh) are read at the origin
  bool reliefFrameUsable =
    !any(isnan(reliefTCoordVSOutput)) && !any(isinf(reliefTCoordVSOutput));
  vec2 reliefEntryTCoord = reliefFrameUsable ? reliefTCoordVSOutput : vec2(0.0);
  reliefGradX = dFdx(reliefEntryTCoord);
  reliefGradY = dFdy(reliefEntryTCoord);
  reliefLod = reliefLevel(reliefTextureSize);
  vec3 reliefViewVC =
    cameraParallel == 1 ? vec3(0.0, 0.0, -1.0) : normalize(reliefPositionVSOutput);
  // the side the mesh's winding faces: a mirroring actor matrix turns the screen's round
  bool reliefFrontFacing = gl_FrontFacing == (reliefMirrored == 0);
#ifdef RELIEF_DERIVATIVE_FRAME
  // the derivative frame (seed 003): the triangle's own mapping, from how position and
  // texture coordinates change from pixel to pixel; its normal faces the viewer
  vec3 reliefAlongX = dFdx(reliefPositionVSOutput);
  vec3 reliefAlongY = dFdy(reliefPositionVSOutput);
  vec3 reliefFaceN = cross(reliefAlongX, reliefAlongY);
  reliefFaceN = dot(reliefFaceN, reliefViewVC) > 0.0 ? -reliefFaceN : reliefFaceN;
  reliefFrameN = reliefUnitOr(reliefFaceN, -reliefViewVC);
#ifdef RELIEF_VERTEX_NORMALS
  // smooth: depth along the interpolated normal, turned to the face's visible side;
  // near an outline it may still face away from the viewer, and no ray can go in along
  // it: the face's normal then
  vec3 reliefVertexN = reliefUnitOr(reliefNormalVSOutput, reliefFrameN);
  reliefVertexN = dot(reliefVertexN, reliefFaceN) < 0.0 ? -reliefVertexN : reliefVertexN;
  reliefFrameN = dot(reliefVertexN, reliefViewVC) < -1e-3 ? reliefVertexN : reliefFrameN;
#endif
  ReliefAxes reliefAxes = reliefDerivativeAxes(
    reliefAlongX, reliefAlongY, reliefGradX, reliefGradY, reliefFrameN);
  reliefAxisU = reliefAxes.u;
  reliefAxisV = reliefAxes.v;
  reliefFrameUsable = reliefFrameUsable && reliefAxes.usable;
#elif defined(RELIEF_TANGENT_FRAME)
  reliefFrameN = normalize(reliefNormalVSOutput);
  vec3 reliefFrameT = normalize(
    reliefTangentVSOutput - reliefFrameN * dot(reliefFrameN, reliefTangentVSOutput));
  vec3 reliefFrameB = cross(reliefFrameN, reliefFrameT);
  // seen from behind, the relief is carved into the back: the normal turns, the
  // texture axes stay
  if (!reliefFrontFacing) { reliefFrameN = -reliefFrameN; }
  vec2 reliefScale = reliefTextureScaleVSOutput;
  if (abs(reliefScale.x) < 1e-20) { reliefScale.x = 1e-20; }
  if (abs(reliefScale.y) < 1e-20) { reliefScale.y = 1e-20; }
  reliefAxisU = reliefFrameT / reliefScale.x;
  reliefAxisV = reliefFrameB / reliefScale.y;
#else
#error "a relief frame: define RELIEF_TANGENT_FRAME or RELIEF_DERIVATIVE_FRAME"
#endif
#if defined(RELIEF_QUADRIC) && !defined(RELIEF_TANGENT_FRAME)
#error "the quadric frame builds on the tangent frame: define RELIEF_TANGENT_FRAME too"
#endif

  // search; the hit's distance along the view ray (world units), and the tilt of the
  // reference surface there in view space (the quadric's slope; none for flat frames)
  float reliefHitDistance = 0.0;
  vec3 reliefSurfaceSlope = vec3(0.0);
  if (reliefDepthScale > 0.0 && reliefFrameUsable)
  {
#ifdef RELIEF_QUADRIC
    // the curved frame (seed 000 s3.1-3.4): the view ray bends below the quadric; a ray
    // that comes back out of it without meeting the relief is past the silhouette
    vec3 reliefViewTF = vec3(dot(reliefViewVC, reliefFrameT), dot(reliefViewVC, reliefFrameB),
      dot(reliefViewVC, reliefFrameN));
    // a back face draws relief only where the ray reaches it from inside the shape
    if (!reliefFrontFacing && reliefTwoSided == 0 &&
      reliefQuadricBehindOutline(
        reliefQuadricDepthTerms(reliefViewTF, reliefQuadricVSOutput, reliefDepthScale),
        cameraParallel == 1 ? 1e30 : length(reliefPositionVSOutput)))
    {
      discard;
    }
    vec2 reliefQuadric = reliefFrontFacing ? reliefQuadricVSOutput : -reliefQuadricVSOutput;
    vec2 reliefTerms = reliefQuadricDepthTerms(reliefViewTF, reliefQuadric, reliefDepthScale);
    float reliefRange = reliefQuadricRange(reliefTerms);
    ReliefRay reliefViewRayTS = reliefQuadricViewRay(
      reliefEntryTCoord, reliefViewTF, reliefScale, reliefTerms, reliefRange);
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
    vec2 reliefQuadricSlope = -2.0 * reliefQuadric * reliefViewTF.xy * reliefHitDistance;
    reliefSurfaceSlope = reliefFrameT * reliefQuadricSlope.x + reliefFrameB * reliefQuadricSlope.y;
#else
    ReliefRay reliefViewRayTS =
      reliefViewRay(reliefEntryTCoord, reliefToTexture(reliefViewVC));
    reliefViewHit = reliefSearch(reliefViewRayTS, reliefLinearSteps, reliefBinarySteps);
    reliefHitDistance = reliefViewHit.position.z * reliefDepthScale /
      max(-dot(reliefViewVC, reliefFrameN), 1e-6);
#endif
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
  // the depth's gradient along the surface tilts the normal: n = N + s_z grad(depth)
  vec3 reliefFieldSlopeVC = vec3(0.0);
  if (reliefFrameUsable)
  {
    vec2 reliefSlope = reliefDepthGradient(reliefHitTCoord) * max(reliefDepthScale, 0.0);
    reliefFieldSlopeVC = reliefAxisU * reliefSlope.x + reliefAxisV * reliefSlope.y;
  }
  vec3 reliefLitNormalVC = normalize(reliefFrameN + reliefSurfaceSlope + reliefFieldSlopeVC);
  vec4 reliefHitDC = reliefVCDCMatrix * vec4(reliefHitVC, 1.0);
  float reliefFragDepth = reliefDepthCorrection == 1 ?
    clamp(0.5 * reliefHitDC.z / reliefHitDC.w + 0.5, 0.0, 1.0) : gl_FragCoord.z;
