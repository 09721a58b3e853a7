// The relief shader sources as ReliefCpuMirror.h compiles them, once per frame and
// configuration: included (no include guard) with RELIEF_MIRROR_FRAME naming the frame's
// file, RELIEF_MIRROR_FLAT_FRAME set for a flat frame, and the frame's defines set first,
// as the mapper sets them. The order is the fragment shader's.
#include "vtkReliefCommon.glsl"
#include "vtkReliefSearch.glsl"
#include "vtkReliefGridSearch.glsl"
#include "vtkReliefSafetySearch.glsl"
#include "vtkReliefSlopeSearch.glsl"
#include "vtkReliefConeSearch.glsl"
#include "vtkReliefAutomaticSearch.glsl"
#include "vtkReliefPathSearch.glsl"
#ifndef RELIEF_CURVED_FRAME
// path features on a relief base (straight rays only), the field searched exactly
#define RELIEF_PATH_BASE_SEARCH reliefSearchExactDDA
#include "vtkReliefPathOnRelief.glsl"
#undef RELIEF_PATH_BASE_SEARCH
#endif
#include "vtkReliefTangentBasis.glsl"
#ifdef RELIEF_MIRROR_FLAT_FRAME
#include "vtkReliefFlatFrame.glsl"
#undef RELIEF_MIRROR_FLAT_FRAME
#endif
#include RELIEF_MIRROR_FRAME
#undef RELIEF_MIRROR_FRAME
