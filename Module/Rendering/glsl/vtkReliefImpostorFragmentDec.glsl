// vtkRelief impostor fragment declarations (vtkOpenGLReliefImpostorMapper): the views'
// textures, one layer per view, and the reads the searches and the impostor frame make
// through them (vtkReliefCommon.glsl's macros, on the selected view's layer).
uniform sampler2DArray reliefImpostorDepths;   // the views' depths, 16 bits, clamped
uniform sampler2DArray reliefImpostorPyramids; // MaximumMipmap's levels 1 up, 16 bits
uniform sampler2DArray reliefImpostorColours;  // RGB, empty texels filled, mipmapped
uniform sampler2DArray reliefImpostorNormals;  // octahedral, in the views' frames, mipmapped
uniform mat4 reliefImpostorNormalFrames[RELIEF_IMPOSTOR_VIEWS]; // the views' frames to model
uniform vec2 reliefTextureSize;                // depth texels per view side
uniform mat4 reliefImpostorProjections[RELIEF_IMPOSTOR_VIEWS]; // model to the views
uniform float reliefImpostorDepthRatios[RELIEF_IMPOSTOR_VIEWS]; // box depth / face size
uniform vec3 reliefImpostorLow;                // the capture's box, model coordinates
uniform vec3 reliefImpostorHigh;
uniform mat4 reliefImpostorVCMC;               // view to model, without VBO shift/scale
uniform mat4 reliefImpostorMCVC;
uniform mat3 reliefImpostorNormalMatrix;       // model to view for normals
uniform mat4 reliefVCDCMatrix;
uniform float reliefNearVC;                    // the near plane's distance
uniform float reliefPixelSpread;   // a pixel's size per unit of distance (perspective), or
                                   // its size (parallel projection), in view units
uniform float reliefColourTexelsPerUnit;       // colour texels per view unit
uniform int reliefLinearSteps;
uniform int reliefBinarySteps;
uniform int reliefDisplayMode;                 // 0 shaded, 1 sample count
uniform int reliefImpostorScalarColours;       // 1: the colours replace the property's
in vec4 reliefImpostorVC;

float reliefImpostorLayer = 0.0; // the view the reads below read
// gl_FragCoord's depth and 1/w at the hit: VTK's code that reads the fragment's depth
// (the shadow-map baker, depth peeling) is made to read these (vtkOpenGLReliefImpostorMapper)
float reliefFragCoordZ = 0.0;
float reliefFragCoordW = 1.0;
#define RELIEF_IMPOSTOR_SELECT(view) reliefImpostorLayer = float(view)
#define RELIEF_IMPOSTOR_PROJECTION(view) reliefImpostorProjections[view]
#define RELIEF_IMPOSTOR_DEPTH_RATIO(view) reliefImpostorDepthRatios[view]
#define RELIEF_DEPTH(uv) textureLod(reliefImpostorDepths, vec3(uv, reliefImpostorLayer), 0.0).r
#define RELIEF_DEPTH_SIZE reliefTextureSize
#define RELIEF_DEPTH_REPEATS false // the views are clamped at their edges
#ifdef GL_ARB_texture_gather
#define RELIEF_CELL_DEPTHS(cell) textureGather(reliefImpostorDepths, \
  vec3(((cell) + 1.0) / reliefTextureSize, reliefImpostorLayer)).wzxy
#else
#define RELIEF_CELL_DEPTHS(cell) reliefCellDepths(cell)
vec4 reliefCellDepths(vec2 cell)
{
  ivec2 last = ivec2(reliefTextureSize) - 1;
  ivec2 low = clamp(ivec2(cell), ivec2(0), last);
  ivec2 high = clamp(ivec2(cell) + 1, ivec2(0), last);
  int layer = int(reliefImpostorLayer);
  return vec4(texelFetch(reliefImpostorDepths, ivec3(low, layer), 0).r,
    texelFetch(reliefImpostorDepths, ivec3(high.x, low.y, layer), 0).r,
    texelFetch(reliefImpostorDepths, ivec3(low.x, high.y, layer), 0).r,
    texelFetch(reliefImpostorDepths, ivec3(high, layer), 0).r);
}
#endif
// vtkMaximumMipmapFilter's pyramid of each view, as vtkReliefSearchMethod describes it:
// level 0, each cell's least corner depth, from the depths; the levels above from the
// atlas's column right of level 0, which alone is uploaded
uniform int reliefPyramidTop;
uniform float reliefPyramidRows[32];
float reliefImpostorPyramidDepth(vec2 node, int level)
{
  if (level == 0)
  {
    vec4 corners = RELIEF_CELL_DEPTHS(node);
    return min(min(corners.x, corners.y), min(corners.z, corners.w));
  }
  return texelFetch(reliefImpostorPyramids,
    ivec3(ivec2(node) + ivec2(0, reliefPyramidRows[level]), int(reliefImpostorLayer)), 0).r;
}
#define RELIEF_PYRAMID_DEPTH(node, level) reliefImpostorPyramidDepth(vec2(node), level)
#define RELIEF_PYRAMID_TOP reliefPyramidTop

// A normal from its octahedral coordinates (vtkOpenGLReliefImpostorMapper encodes them),
// not normalized
vec3 reliefImpostorOctahedralNormal(vec2 encoded)
{
  vec3 normal = vec3(encoded, 1.0 - abs(encoded.x) - abs(encoded.y));
  float fold = max(-normal.z, 0.0);
  normal.x += normal.x >= 0.0 ? -fold : fold;
  normal.y += normal.y >= 0.0 ? -fold : fold;
  return normal;
}

//VTK::Relief::Common
//VTK::Relief::Search
//VTK::Relief::Frame
