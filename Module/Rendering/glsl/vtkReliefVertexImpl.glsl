  reliefPositionVSOutput = (MCVCMatrix * vertexMC).xyz;
  reliefTCoordVSOutput = reliefTCoordMC;
  reliefFrameVertex();
