  reliefPositionVC = (MCVCMatrix * vertexMC).xyz;
  reliefNormalVC = reliefNormalMatrix * reliefNormalMC;
  vec3 reliefTangentView = reliefDirectionMatrix * reliefTangentMC;
  vec3 reliefBitangentView = reliefDirectionMatrix * cross(reliefNormalMC, reliefTangentMC);
  reliefTangentVC = reliefTangentView;
  // an actor's scale stretches the tile as seen from the camera: carry it into s_x, s_y
  reliefTextureScaleVC = reliefTextureScaleMC *
    vec2(length(reliefTangentView), length(reliefBitangentView));
  reliefTCoord = reliefTCoordMC;
