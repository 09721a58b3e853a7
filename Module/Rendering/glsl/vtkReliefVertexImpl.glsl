  reliefPositionVSOutput = (MCVCMatrix * vertexMC).xyz;
  reliefTCoordVSOutput = reliefTCoordMC;
#ifdef RELIEF_VERTEX_NORMALS
  reliefNormalVSOutput = reliefNormalMatrix * reliefNormalMC;
#endif
#ifdef RELIEF_TANGENT_FRAME
  // unit, perpendicular model axes: only the actor's transform may stretch them
  vec3 reliefUnitNormalMC = normalize(reliefNormalMC);
  vec3 reliefUnitTangentMC = normalize(reliefTangentMC -
    reliefUnitNormalMC * dot(reliefUnitNormalMC, reliefTangentMC));
  vec3 reliefTangentView = reliefDirectionMatrix * reliefUnitTangentMC;
  vec3 reliefBitangentView =
    reliefDirectionMatrix * cross(reliefUnitNormalMC, reliefUnitTangentMC);
  reliefTangentVSOutput = reliefTangentView;
  // an actor's scale stretches the tile as seen from the camera: carry it into s_x, s_y
  reliefTextureScaleVSOutput = reliefTextureScaleMC *
    vec2(length(reliefTangentView), length(reliefBitangentView));
#endif
#ifdef RELIEF_QUADRIC
  // curvature is 1 / length: an actor's scale k turns a into a / k; NaN is a plane
  reliefQuadricVSOutput = any(isnan(reliefQuadricMC)) || any(isinf(reliefQuadricMC)) ?
    vec2(0.0) : reliefQuadricMC / vec2(length(reliefTangentView), length(reliefBitangentView));
#endif
