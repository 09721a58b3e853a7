    reliefPositionGSOutput = reliefPositionVSOutput[i];
    reliefTCoordGSOutput = reliefTCoordVSOutput[i];
    reliefFrameGeometry(i);
