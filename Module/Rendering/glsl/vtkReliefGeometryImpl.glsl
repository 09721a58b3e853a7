    reliefPositionGSOutput = reliefPositionVSOutput[i];
    reliefTCoordGSOutput = reliefTCoordVSOutput[i];
#ifdef RELIEF_VERTEX_NORMALS
    reliefNormalGSOutput = reliefNormalVSOutput[i];
#endif
#ifdef RELIEF_TANGENT_FRAME
    reliefTangentGSOutput = reliefTangentVSOutput[i];
    reliefTextureScaleGSOutput = reliefTextureScaleVSOutput[i];
#endif
#ifdef RELIEF_QUADRIC
    reliefQuadricGSOutput = reliefQuadricVSOutput[i];
#endif
