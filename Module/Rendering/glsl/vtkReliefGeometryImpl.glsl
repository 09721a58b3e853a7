    reliefPositionGSOutput = reliefPositionVSOutput[i];
    reliefNormalGSOutput = reliefNormalVSOutput[i];
    reliefTangentGSOutput = reliefTangentVSOutput[i];
    reliefTCoordGSOutput = reliefTCoordVSOutput[i];
    reliefTextureScaleGSOutput = reliefTextureScaleVSOutput[i];
#ifdef RELIEF_QUADRIC
    reliefQuadricGSOutput = reliefQuadricVSOutput[i];
#endif
