// The relief shader sources as ReliefCpuMirror.h compiles them, once per frame and
// configuration: included (no include guard) with RELIEF_MIRROR_FRAME naming the frame's
// file and the frame's defines set. The order is the fragment shader's.
#include "vtkReliefCommon.glsl"
#include "vtkReliefSearch.glsl"
#include "vtkReliefGridSearch.glsl"
#include "vtkReliefSafetySearch.glsl"
#include "vtkReliefConeSearch.glsl"
#include "vtkReliefTangentBasis.glsl"
#include RELIEF_MIRROR_FRAME
#undef RELIEF_MIRROR_FRAME
