    reliefPositionGSOutput = reliefPositionVSOutput[i];
    reliefNormalGSOutput = reliefNormalVSOutput[i];
    reliefTangentGSOutput = reliefTangentVSOutput[i];
    reliefTCoordGSOutput = reliefTCoordVSOutput[i];
    reliefTextureScaleGSOutput = reliefTextureScaleVSOutput[i];
