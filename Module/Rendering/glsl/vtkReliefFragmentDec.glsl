// vtkRelief fragment declarations: uniforms, the interpolated frame, the search, and
// the per-light shadow query used by VTK's lighting code.
uniform sampler2D reliefDepthTexture; // vtkReliefTextureFilter's depth, 16-bit
#ifdef RELIEF_INPUT_NORMALS
uniform sampler2D reliefNormalTexture; // (nx, ny) of the normal map given with the heights
#endif
uniform sampler2D reliefAccelerationTexture; // what the search method reads besides
uniform vec2 reliefTextureSize;    // texels per tile
uniform float reliefNormalRatio;   // the filter's DepthToTexelRatio (input normals only)
uniform float reliefDepthScale;    // s_z: world depth of depth 1; <= 0 disables the relief
uniform int reliefLinearSteps;
uniform int reliefBinarySteps;
uniform int reliefSelfShadowing;
uniform int reliefDepthCorrection;
uniform int reliefDisplayMode;     // 0 shaded, 1 sample count
uniform int reliefTwoSided;        // 1: back faces carry relief wherever they are drawn
uniform int reliefMirrored;        // 1: the actor's matrix mirrors (negative determinant)
uniform mat4 reliefVCDCMatrix;
in vec3 reliefPositionVSOutput;
in vec2 reliefTCoordVSOutput;

// Derivatives of the entry coordinates, taken once outside the search loops: every read
// at a ray point uses the mipmap level they give, exactly the level textureGrad with
// them would pick, computed once instead of at every read.
vec2 reliefGradX;
vec2 reliefGradY;
float reliefLod;

float reliefLevel(vec2 texels)
{
  vec2 alongX = reliefGradX * texels;
  vec2 alongY = reliefGradY * texels;
  return 0.5 * log2(max(dot(alongX, alongX), dot(alongY, alongY)));
}

// A texture read at a point of the view ray, filtered as at its entry point: once a
// fragment (colours, normals), so through textureGrad, which costs nothing here. Mesa's
// llvmpipe reads an 8-bit colour texture at about twice the coordinates where an
// explicit level (textureLod) differs between the fragments it shades together: a
// two-pixel column of wrong colour wherever the level crosses a whole number.
#define reliefTextureAtRay(sampler, uv) textureGrad(sampler, uv, reliefGradX, reliefGradY)

#define RELIEF_DEPTH(uv) textureLod(reliefDepthTexture, uv, reliefLod).r
#define RELIEF_DEPTH_SIZE reliefTextureSize
// a cell's corners (i, j), (i+1, j), (i, j+1), (i+1, j+1), the texture repeating
#ifdef GL_ARB_texture_gather
#define RELIEF_CELL_DEPTHS(cell) \
  textureGather(reliefDepthTexture, ((cell) + 1.0) / reliefTextureSize).wzxy
#else
#define RELIEF_CELL_DEPTHS(cell) reliefCellDepths(cell)
vec4 reliefCellDepths(vec2 cell)
{
  ivec2 low = ivec2(mod(cell, reliefTextureSize));
  ivec2 high = ivec2(mod(cell + 1.0, reliefTextureSize));
  return vec4(texelFetch(reliefDepthTexture, low, 0).r,
    texelFetch(reliefDepthTexture, ivec2(high.x, low.y), 0).r,
    texelFetch(reliefDepthTexture, ivec2(low.x, high.y), 0).r,
    texelFetch(reliefDepthTexture, high, 0).r);
}
#endif
// The depth gradient (change of depth per unit of u and v) at a hit, at the level the
// search read there: central differences one texel of that level apart, which at level 0
// are exactly the bilinear blend of vtkReliefTextureFilter's per-texel normals, so the
// shading slopes are those of the field searched; or the normal map's, read as the
// filter encodes it.
vec2 reliefDepthGradient(vec2 uv)
{
#ifdef RELIEF_INPUT_NORMALS
  vec2 normalXY = reliefTextureAtRay(reliefNormalTexture, uv).xy;
  float normalZ = sqrt(max(1.0 - dot(normalXY, normalXY), 0.0));
  return normalXY / (max(normalZ, 1e-4) * reliefNormalRatio) * reliefTextureSize;
#else
  vec2 texel = exp2(max(reliefLod, 0.0)) / reliefTextureSize;
  float alongU = RELIEF_DEPTH(uv + vec2(texel.x, 0.0)) - RELIEF_DEPTH(uv - vec2(texel.x, 0.0));
  float alongV = RELIEF_DEPTH(uv + vec2(0.0, texel.y)) - RELIEF_DEPTH(uv - vec2(0.0, texel.y));
  return 0.5 * vec2(alongU / texel.x, alongV / texel.y);
#endif
}

//VTK::Relief::Common
//VTK::Relief::Search
#ifndef RELIEF_SEARCH
#error "no search method: the mapper defines RELIEF_SEARCH as one of the search functions"
#endif
//VTK::Relief::Frame

// The frame's shading basis, for the lighting: gradients of u and v in view space, and
// the unit normal depth is measured against.
vec3 reliefAxisU;
vec3 reliefAxisV;
vec3 reliefFrameN;
ReliefHit reliefViewHit;

// A view-space direction in texture-space units (du, dv, ddepth); depth grows inward.
vec3 reliefToTexture(vec3 directionVC)
{
  return reliefFlatDirection(
    directionVC, reliefAxisU, reliefAxisV, reliefFrameN, reliefDepthScale);
}

// Visibility (0 or 1) of a light seen from the hit, toLightVC pointing to the light.
float reliefShadow(vec3 toLightVC)
{
  if (reliefSelfShadowing == 0 || reliefDepthScale <= 0.0)
  {
    return 1.0;
  }
  return reliefLightVisibility(
    reliefViewHit.clear, reliefToTexture(toLightVC), reliefLinearSteps);
}

//VTK::Relief::TCoordAtHit
