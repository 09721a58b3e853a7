// vtkRelief fragment declarations: uniforms, the interpolated frame, the search, the
// footprint's normals and the per-light diffuse term and shadow query that VTK's
// lighting code is made to call (vtkReliefShaderRewrites::LightThrough).
uniform sampler2D reliefDepthTexture; // vtkReliefTextureFilter's depth, 16-bit
#ifdef RELIEF_INPUT_NORMALS
uniform sampler2D reliefNormalTexture; // (nx, ny) of the normal map given with the heights
#endif
#ifdef RELIEF_ACCELERATION_CODES
uniform usampler2D reliefAccelerationTexture; // the search's acceleration image, as integers
#else
uniform sampler2D reliefAccelerationTexture; // what the search method reads besides depths
#endif
uniform vec2 reliefTextureSize;    // texels per tile
uniform float reliefNormalRatio;   // the filter's DepthToTexelRatio (input normals only)
uniform float reliefDepthScale;    // s_z: world depth of depth 1; <= 0 disables the relief
uniform float reliefScreenTolerance; // pixels the Automatic search may leave out
uniform int reliefLinearSteps;
uniform int reliefBinarySteps;
uniform int reliefSelfShadowing;
uniform int reliefDepthCorrection;
uniform int reliefDisplayMode;     // 0 shaded, 1 sample count
uniform int reliefTwoSided;        // 1: back faces carry relief wherever they are drawn
uniform int reliefMirrored;        // 1: the actor's matrix mirrors (negative determinant)
uniform mat4 reliefVCDCMatrix;
#ifndef RELIEF_DEEPEST
#define RELIEF_DEEPEST 1.0
#endif
#ifdef RELIEF_PATH_FEATURES
uniform sampler2D reliefPathGrid; // vtkPathFeatureTextureFilter's grid, a texel per cell
uniform sampler2D reliefPathData; // and its data, read as one array of texels, in rows of
                                  // 2^RELIEF_PATH_DATA_WIDTH_BITS (or one shorter row)
#define RELIEF_PATH_TEXEL(index) texelFetch(reliefPathData, \
  ivec2((index) & ((1 << RELIEF_PATH_DATA_WIDTH_BITS) - 1), (index) >> RELIEF_PATH_DATA_WIDTH_BITS), 0)
#define RELIEF_PATH_CELL(cell) \
  texelFetch(reliefPathGrid, ivec2(mod(cell, vec2(textureSize(reliefPathGrid, 0)))), 0)
#endif
in vec3 reliefPositionVSOutput;
in vec2 reliefTCoordVSOutput;

// Derivatives of the entry coordinates, taken once outside the search loops, for the
// colour textures read at the hit (reliefTextureAtRay).
vec2 reliefGradX;
vec2 reliefGradY;

// A texture read at a point of the view ray, filtered as at its entry point: once a
// fragment (colours, normals), so through textureGrad, which costs nothing here. Mesa's
// llvmpipe reads an 8-bit colour texture at about twice the coordinates where an
// explicit level (textureLod) differs between the fragments it shades together: a
// two-pixel column of wrong colour wherever the level crosses a whole number.
#define reliefTextureAtRay(sampler, uv) textureGrad(sampler, uv, reliefGradX, reliefGradY)
// A colour texture's read (vtkReliefShaderRewrites::ReadTexturesThrough). The actor's
// textures colour what the path features' own materials do not: VTK multiplies the lit
// colour by the texture's, which reads white for the materials' share of the footprint
// (reliefPathMaterialShare; where a pixel holds both, the two are mixed by their shares).
#ifdef RELIEF_PATH_FEATURES
float reliefPathMaterialShare();
#define reliefColourAtRay(sampler, uv) \
  mix(reliefTextureAtRay(sampler, uv), vec4(1.0), reliefPathMaterialShare())
#else
#define reliefColourAtRay(sampler, uv) reliefTextureAtRay(sampler, uv)
#endif

// Depths are read at full resolution, whatever the footprint: the searches intersect and
// the shading lights the field itself, never a mipmap's average of it, which lowers steps
// and tilts their walls away from the viewer (too dark, or too bright, under minification
// and at oblique views: Documentation/results.md, shading).
#define RELIEF_DEPTH(uv) textureLod(reliefDepthTexture, uv, 0.0).r
#define RELIEF_DEPTH_SIZE reliefTextureSize
#define RELIEF_DEPTH_REPEATS true
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

//VTK::Relief::Common
//VTK::Relief::Search
#ifndef RELIEF_SEARCH
#error "no search method: the mapper defines RELIEF_SEARCH as one of the search functions"
#endif
//VTK::Relief::Frame

// A frame's view ray of `fragment`, with its run on screen for the Automatic search.
ReliefRay reliefScreenViewRay(ReliefFrame frame, ReliefFragment fragment)
{
  ReliefRay ray = reliefFrameViewRay(frame, fragment);
  ray.screenRun = reliefScreenRun(vec2(ray.direction.x, ray.direction.y),
    fragment.tcoordAlongX, fragment.tcoordAlongY, reliefScreenTolerance);
  return ray;
}

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
#if defined(RELIEF_PATH_RELIEF_BASE)
  return reliefPathOnReliefLightVisibility(
    reliefViewHit.clear, reliefToTexture(toLightVC), reliefLinearSteps, reliefBinarySteps);
#elif defined(RELIEF_PATH_FEATURES)
  return reliefPathLightVisibility(reliefViewHit.clear, reliefToTexture(toLightVC));
#else
  return reliefLightVisibility(
    reliefViewHit.clear, reliefToTexture(toLightVC), reliefLinearSteps);
#endif
}

// The field's unit normal at `uv`, on the frame's surface tilted by `slope`: the depth's
// gradient along the surface tilts it, n = N + s_z grad(depth); or the normal map's,
// read as the filter encodes it.
vec3 reliefFieldNormal(vec2 uv, vec3 slope)
{
#if defined(RELIEF_PATH_FEATURES)
  // the last path search's facet: its outward covector (a, b, c) in (u, v, depth) is
  // a axisU + b axisV - c N / s_z in view space
  vec3 covector = reliefPathHitNormal;
  return normalize(max(reliefDepthScale, 0.0) * (reliefAxisU * covector.x +
    reliefAxisV * covector.y) - covector.z * (reliefFrameN + slope));
#else
#ifdef RELIEF_INPUT_NORMALS
  vec2 normalXY = reliefTextureAtRay(reliefNormalTexture, uv).xy;
  float normalZ = sqrt(max(1.0 - dot(normalXY, normalXY), 0.0));
  vec2 gradient = normalXY / (max(normalZ, 1e-4) * reliefNormalRatio) * reliefTextureSize;
#else
  vec2 gradient = reliefFieldGradient(uv);
#endif
  return normalize(reliefFrameN + slope +
    max(reliefDepthScale, 0.0) * (reliefAxisU * gradient.x + reliefAxisV * gradient.y));
#endif
}

// The normals the pixel's footprint is lit with, and their weights (reliefShadeFootprint):
// Lambert's cosine toward a light is the weighted mean of their clamped cosines
// (reliefDiffuse), what a camera that averages the pixel sees, not the cosine of the one
// normal the pixel's centre happens to hold.
vec3 reliefFootprintNormals[5];
float reliefFootprintWeights[5];
int reliefFootprintCount = 0;
#ifdef RELIEF_PATH_FEATURES
float reliefFootprintMaterials[5]; // the material each normal's search met
#endif

void reliefAddFootprintNormal(vec3 normal, float weight)
{
  reliefFootprintNormals[reliefFootprintCount] = normal;
  reliefFootprintWeights[reliefFootprintCount] = weight;
#ifdef RELIEF_PATH_FEATURES
  reliefFootprintMaterials[reliefFootprintCount] = reliefPathHitMaterial;
#endif
  reliefFootprintCount += 1;
}

#ifdef RELIEF_PATH_FEATURES
// The weight of the footprint's normals whose searches met a material of their own.
float reliefPathMaterialShare()
{
  float share = 0.0;
  for (int k = 0; k < reliefFootprintCount; ++k)
  {
    share += reliefFootprintMaterials[k] >= 0.0 ? reliefFootprintWeights[k] : 0.0;
  }
  return share;
}

// The colours VTK's lighting reads, as the footprint's materials weighted like its normals:
// the actor's where a search met no material of its own; a material's colour is ambient
// and diffuse, as scalars colour both.
void reliefPathShadeMaterials(inout vec3 ambient, inout vec3 diffuse, inout vec3 specular,
  inout float power, float ambientIntensity, float diffuseIntensity)
{
  vec3 mixedAmbient = vec3(0.0);
  vec3 mixedDiffuse = vec3(0.0);
  vec3 mixedSpecular = vec3(0.0);
  float mixedPower = 0.0;
  for (int k = 0; k < reliefFootprintCount; ++k)
  {
    float weight = reliefFootprintWeights[k];
    int material = int(reliefFootprintMaterials[k]);
    if (material < 0)
    {
      mixedAmbient += weight * ambient;
      mixedDiffuse += weight * diffuse;
      mixedSpecular += weight * specular;
      mixedPower += weight * power;
    }
    else
    {
      vec4 colour = RELIEF_PATH_TEXEL(material);
      mixedAmbient += weight * ambientIntensity * colour.rgb;
      mixedDiffuse += weight * diffuseIntensity * colour.rgb;
      mixedSpecular += weight * vec3(colour.a);
      mixedPower += weight * RELIEF_PATH_TEXEL(material + 1).x;
    }
  }
  ambient = mixedAmbient;
  diffuse = mixedDiffuse;
  specular = mixedSpecular;
  power = mixedPower;
}
#endif

float reliefDiffuse(vec3 toLight)
{
  float cosine = 0.0;
  for (int k = 0; k < reliefFootprintCount; ++k)
  {
    cosine += reliefFootprintWeights[k] * max(0.0, dot(reliefFootprintNormals[k], toLight));
  }
  return cosine;
}

// The footprint's normals, weighted, as one: the normal VTK's lighting reads (specular).
vec3 reliefFootprintMean(vec3 fallback)
{
  vec3 mean = vec3(0.0);
  for (int k = 0; k < reliefFootprintCount; ++k)
  {
    mean += reliefFootprintWeights[k] * reliefFootprintNormals[k];
  }
  return dot(mean, mean) > 1e-12 ? normalize(mean) : fallback;
}

// Four points of a pixel, a rotated grid: no two share a row or a column, so that edges
// near the pixels' axes are sampled at four offsets (Akenine-Moller, Haines and Hoffman,
// Real-Time Rendering, 3rd ed. 2008, s5.6.2).
const vec2 reliefRotatedGrid[4] = vec2[4](vec2(-0.125, -0.375), vec2(0.375, -0.125),
  vec2(0.125, 0.375), vec2(-0.375, 0.125));

#ifdef RELIEF_PATH_FEATURES
// The normals and materials the path features' footprint is lit with (reliefShadeFootprint).
// Path features have sharp edges at every scale: wherever a feature's reach comes within
// the pixel of the view ray's path (judged, as the path-feature paper does, s5.7, on the
// cells the view ray passed) the pixel is antialiased, elsewhere it all meets the plain
// base. Region sampling (s5.7) where one element alone is that near: the footprint's
// regions across it (reliefPathRegions), each lit as the ray at its middle meets that
// element (reliefPathRegionSurfaces) and weighted by its share of the pixel (one region:
// all of the pixel sees what its centre sees); where the regions cannot tell (an end, an
// intersection, a profile that both cuts and adds, more than four regions), the rays
// through four points of the pixel (reliefRotatedGrid), each walked through all the
// features and lit where it hits.
vec3 reliefPathShadeFootprint(ReliefFrame frame, ReliefFragment fragment, vec2 uv, vec3 slope,
  vec3 centre, inout int samples)
{
  reliefFootprintCount = 0;
  float reach = reliefPathPixelReach(fragment.tcoordAlongX, fragment.tcoordAlongY);
  // (no walk, and no nearest feature, where DepthScale is 0)
  bool near = reliefDepthScale > 0.0 && reliefPathNearest.gap <= reach;
  ReliefRay ray = reliefScreenViewRay(frame, fragment);
  ReliefPathNearest nearest = reliefPathNearest;
  ReliefPathRegions regions = reliefPathNoRegions();
#ifdef RELIEF_PATH_RELIEF_BASE
  // on a relief base (vtkReliefPathOnRelief.glsl) the regions' plain base is not plain:
  // the footprint's rays wherever a feature is near; elsewhere, as the relief mapper's
  // (reliefShadeFootprint), blended in as the pixel holds from a third to 0.7 of a texel
  // of the field, whose detail then aliases, searching the field alone, in a loop of their
  // own (on llvmpipe a loop no fragment of the eight run together needs costs one pass,
  // and most pixels are far from every feature)
  float side = min(length(fragment.tcoordAlongX * reliefTextureSize),
    length(fragment.tcoordAlongY * reliefTextureSize));
  float searched = reliefDepthScale > 0.0 ? smoothstep(0.35, 0.7, side) : 0.0;
  bool fieldAlone = !near && searched > 0.0;
  if (fieldAlone && searched < 1.0)
  {
    reliefAddFootprintNormal(centre, 1.0 - searched);
  }
  for (int k = 0; k < 4 && fieldAlone; ++k)
  {
    ReliefFragment quarter = fragment;
    quarter.tcoord += reliefRotatedGrid[k].x * fragment.tcoordAlongX +
      reliefRotatedGrid[k].y * fragment.tcoordAlongY;
    ReliefHit hit = reliefPathBaseAlone(
      reliefScreenViewRay(frame, quarter), reliefLinearSteps, reliefBinarySteps);
    samples += hit.samples;
    reliefAddFootprintNormal(
      reliefFieldNormal(hit.position.xy - round(hit.position.xy - uv), slope), 0.25 * searched);
  }
  if (fieldAlone)
  {
    return reliefFootprintMean(centre);
  }
#else
  if (near && nearest.second > reach)
  {
    regions = reliefPathRegions(ray, nearest, fragment.tcoordAlongX, fragment.tcoordAlongY);
  }
#endif
  if (!near || regions.count == 1)
  {
    reliefAddFootprintNormal(centre, 1.0);
    return centre;
  }
  if (regions.count > 1)
  {
    samples += 1; // one element, tested for the regions' rays together
    for (int k = 0; k < 4 && k < regions.count; ++k)
    {
      reliefPathHitNormal = vec3(reliefPathEntry(regions.normalsU, k),
        reliefPathEntry(regions.normalsV, k), reliefPathEntry(regions.normalsDepth, k));
      reliefPathHitMaterial = reliefPathEntry(regions.materials, k);
      reliefAddFootprintNormal(reliefFieldNormal(uv, slope), reliefPathEntry(regions.weights, k));
    }
    return reliefFootprintMean(centre);
  }
  for (int k = 0; k < 4; ++k)
  {
    ReliefFragment quarter = fragment;
    quarter.tcoord += reliefRotatedGrid[k].x * fragment.tcoordAlongX +
      reliefRotatedGrid[k].y * fragment.tcoordAlongY;
    ReliefRay walked = reliefScreenViewRay(frame, quarter);
#ifdef RELIEF_PATH_RELIEF_BASE
    ReliefHit hit = RELIEF_SEARCH(walked, reliefLinearSteps, reliefBinarySteps);
#else
    ReliefHit hit = reliefPathElementWalk(walked, 0, vec2(0.0), false);
#endif
    samples += hit.samples;
    if (!reliefFrameRayLeft(frame, walked, hit))
    {
      reliefAddFootprintNormal(
        reliefFieldNormal(hit.position.xy - round(hit.position.xy - uv), slope), 1.0);
    }
  }
  for (int k = 0; k < reliefFootprintCount; ++k)
  {
    reliefFootprintWeights[k] /= float(reliefFootprintCount);
  }
  if (reliefFootprintCount == 0)
  {
    reliefAddFootprintNormal(centre, 1.0); // no quarter's ray met the field
  }
  return reliefFootprintMean(centre);
}
#endif

// The normals the pixel's footprint is lit with (reliefFootprintNormals), and their mean,
// the normal VTK's lighting reads otherwise (specular): the hit's own where a pixel holds
// less than a third of a texel, or with footprint shading off; from 0.7 texels on, those
// of the rays through four points of the pixel (reliefRotatedGrid), each searched and
// lit where it hits; in between, both, weighted (no seam). Point-sampled normals alias;
// a mipmap's normal lights a step's walls for the whole footprint and seen obliquely
// averages away what faces the viewer (Documentation/results.md, shading). The
// footprint is the texels between neighbouring pixels' entries (the entry's
// derivatives), measured along its shorter side. `samples` counts on. A normal map is
// read filtered over the footprint already (reliefTextureAtRay). Path features have
// their own (reliefPathShadeFootprint).
vec3 reliefShadeFootprint(
  ReliefFrame frame, ReliefFragment fragment, vec2 uv, vec3 slope, inout int samples)
{
  vec3 centre = reliefFieldNormal(uv, slope);
#if !defined(RELIEF_FOOTPRINT_SHADING)
  reliefFootprintCount = 0;
  reliefAddFootprintNormal(centre, 1.0); // footprint shading off (RELIEF_FOOTPRINT_SHADING)
  return centre;
#elif defined(RELIEF_PATH_FEATURES)
  return reliefPathShadeFootprint(frame, fragment, uv, slope, centre, samples);
#else
  reliefFootprintCount = 0;
  float side = min(length(fragment.tcoordAlongX * reliefTextureSize),
    length(fragment.tcoordAlongY * reliefTextureSize));
  float searched = reliefDepthScale > 0.0 ? smoothstep(0.35, 0.7, side) : 0.0;
#ifdef RELIEF_INPUT_NORMALS
  searched = 0.0;
#endif
  if (searched < 1.0)
  {
    reliefAddFootprintNormal(centre, 1.0 - searched);
  }
  int first = reliefFootprintCount;
  for (int k = 0; k < 4 && searched > 0.0; ++k)
  {
    ReliefFragment quarter = fragment;
    quarter.tcoord += reliefRotatedGrid[k].x * fragment.tcoordAlongX +
      reliefRotatedGrid[k].y * fragment.tcoordAlongY;
    ReliefRay quarterRay = reliefScreenViewRay(frame, quarter);
    ReliefHit hit = RELIEF_SEARCH(quarterRay, reliefLinearSteps, reliefBinarySteps);
    samples += hit.samples;
    if (!reliefFrameRayLeft(frame, quarterRay, hit))
    {
      vec2 at = hit.position.xy;
      reliefAddFootprintNormal(reliefFieldNormal(at - round(at - uv), slope), searched);
    }
  }
  for (int k = first; k < reliefFootprintCount; ++k)
  {
    reliefFootprintWeights[k] /= float(reliefFootprintCount - first);
  }
  if (searched > 0.0 && reliefFootprintCount == first)
  {
    reliefAddFootprintNormal(centre, searched); // no quarter's ray met the field
  }
  return reliefFootprintMean(centre);
#endif
}

//VTK::Relief::TCoordAtHit
