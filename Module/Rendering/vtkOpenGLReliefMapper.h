/**
 * @class   vtkOpenGLReliefMapper
 * @brief   renders a height map as real relief on any mesh with normals and texture coordinates
 *
 * Relief mapping (Policarpo, Oliveira and Comba 2005): each fragment follows its view
 * ray into the height field below the polygon, in texture space, and shades the first
 * point it meets: self-occlusion, per-pixel lighting with the relief normal, self-shadows
 * and the hit's true depth, so relief interpenetrates the other actors of the scene.
 *
 * Port 0 takes the mesh (point texture coordinates required; normals and tangents are
 * computed when missing, see vtkReliefTangentFrameFilter). The height map goes to
 * SetHeightMapConnection() or SetHeightMapData(): any 2D image, turned into a relief
 * texture by an internal vtkReliefTextureFilter (GetReliefTextureFilter() configures it:
 * height or depth convention, component). DepthScale is the world depth of the deepest
 * level. The actor's property (colours, ambient, diffuse, specular, opacity), its
 * texture (sampled at the hit) and the renderer's lights apply as for any actor.
 *
 * Every search method finds the first intersection of the ray with the height field;
 * the choice is made at shader build time (see SetSearchMethod()). Methods that need
 * an acceleration image (MaximumMipmap's pyramid) build it themselves from the height
 * map, once per change of the map, unless one is given on port 2
 * (SetAccelerationConnection()). Every setter modifies the mapper, as VTK's do; those
 * that change only a uniform (DepthScale, ScreenTolerance, step counts, SelfShadowing,
 * DepthCorrection, DisplayMode, TwoSidedRelief) rebuild neither the shader nor the
 * buffers, the search method, the frame's options and FootprintShading (compiled in or
 * out where the next render finds it changed) only the shader.
 *
 * On the GPU the relief is one 16-bit depth texture at full resolution
 * (vtkReliefTextureFilter's depths lie on its levels): the searches read it, and the
 * shading lights the gradient of its bilinear field at the hit, so the surface lit is the
 * surface searched, at every distance and view angle. A
 * normal map given with the heights (the filter's UseInputNormals) adds its (nx, ny) in
 * 16 bits. ConeStep's cone map takes two bytes a cell (vtkConeStepMapFilter::EncodeCone),
 * the other acceleration images floats. GetTextureBytes() reports the total. Mappers of
 * one window whose height map is the same data share its textures, each made and
 * uploaded once and released with the last mapper that draws it: a multiblock dataset or
 * many actors of one relief cost one copy (GetTextureBytesInUse()).
 */
#ifndef vtkOpenGLReliefMapper_h
#define vtkOpenGLReliefMapper_h

#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkReliefRenderingModule.h"
#include "vtkSmartPointer.h"  // For TangentFrame
#include "vtkWrappingHints.h" // for VTK_NEWINSTANCE

#include <vector> // For MissingShaderTags

class vtkImageData;
class vtkOpenGLReliefTextures;
class vtkReliefAccelerationFilter;
class vtkReliefSearchMethod;
class vtkReliefTangentFrameFilter;
class vtkReliefTextureFilter;
class vtkRenderWindow;
class vtkShaderProgram;

class VTKRELIEFRENDERING_EXPORT vtkOpenGLReliefMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkOpenGLReliefMapper* New();
  vtkTypeMacro(vtkOpenGLReliefMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SearchMethods
  {
    LINEAR = 0,
    LINEAR_BINARY = 1,
    SECANT = 2,
    EXACT_DDA = 3,
    SAFETY_RADIUS = 4,
    CONE_STEP = 5,
    MAXIMUM_MIPMAP = 6,
    AUTOMATIC = 7,
    ROBUST_BINARY = 8,
    SLOPE_MIPMAP = 9
  };

  ///@{
  /**
   * How the view ray meets the height field (Documentation/methods.md compares them).
   * - Automatic (default): per fragment, the least work that keeps the hit within
   *   ScreenTolerance pixels of the exact one. Where the ray's whole run through the
   *   relief spans less than the tolerance on screen, no search: one secant step places
   *   the hit (normal mapping with parallax, 3 samples); where it crosses a few cells,
   *   ExactDDA; over longer runs, ConeStep (so the mapper builds a cone map once per
   *   height map, shared with ConeStep's) or SlopeMipmap (AutomaticAcceleration), ending
   *   within the tolerance; rays over 2048 cells in at most 256 steps. On curved rays
   *   (vtkOpenGLQuadricReliefMapper) fixed steps of half a texel, or of one tolerance
   *   where that is longer on screen, then bisection to a quarter of the tolerance. The
   *   step counts are ignored but for the self-shadow rays.
   * - LinearBinary: LinearSteps fixed steps, then BinarySteps of bisection
   *   (Policarpo et al. 2005). Fast; misses features thinner than a step.
   * - Linear: the fixed steps alone.
   * - Secant: the fixed steps, then BinarySteps of secant refinement (parallax occlusion
   *   mapping, Tatarchuk 2006; 0 refinements is POM's single interpolation).
   * - ExactDDA: every texel cell the ray crosses, each intersected exactly with its
   *   bilinear patch (Baboud and Decoret 2006 s3.3). Exact; cost grows with the run.
   * - SafetyRadius: jumps over squares of cells the ray cannot re-emerge from
   *   (vtkSafetyRadiusFilter), bisects the bracket it finds, then intersects cells
   *   exactly (Baboud and Decoret 2006 s3.4). Exact at SafetyRadiusTolerance 0; a
   *   tolerance e > 0 buys larger jumps for features missed only where the ray passes
   *   within e of their surface.
   * - RobustBinary: SafetyRadius as Baboud and Decoret (2006, s3.4) wrote it: a radius
   *   of 0 is clamped to its own cell, whose exit alone is tested, so a ray may also
   *   pass through one such cell unnoticed. At SafetyRadiusTolerance 0 it costs as
   *   much as SafetyRadius; from about 0.05 its cost no longer grows with the height
   *   map's resolution (Documentation/methods.md).
   * - ConeStep: relaxed cone stepping (Policarpo and Oliveira 2007) with cones valid
   *   for the bilinear field (vtkConeStepMapFilter), a binary refinement, then cells
   *   intersected exactly. Exact.
   * - MaximumMipmap: skips blocks of cells the ray passes over, using a pyramid of
   *   highest points (Tevs et al. 2008), then intersects cells exactly. Exact; about
   *   log n steps.
   * - SlopeMipmap: MaximumMipmap whose nodes also bound the slopes under them and hold
   *   their grandchildren's tops (vtkSlopeMipmapFilter), so that one node read may also
   *   prove that the ray cannot come down to the field before the node's exit, or meets
   *   it at most once there, and passes over the children and grandchildren it clears,
   *   and goes down through the children it does not, without reading them.
   *   Exact; the fewest samples of the exact methods from 30 degrees and the shortest
   *   worst cases, but more work per sample (Documentation/methods.md).
   * The exact methods read the full-resolution field and ignore the step counts.
   * Changing the method rebuilds the shader once.
   */
  void SetSearchMethod(int method);
  vtkGetMacro(SearchMethod, int);
  void SetSearchMethodToLinear() { this->SetSearchMethod(LINEAR); }
  void SetSearchMethodToLinearBinary() { this->SetSearchMethod(LINEAR_BINARY); }
  void SetSearchMethodToSecant() { this->SetSearchMethod(SECANT); }
  void SetSearchMethodToExactDDA() { this->SetSearchMethod(EXACT_DDA); }
  void SetSearchMethodToSafetyRadius() { this->SetSearchMethod(SAFETY_RADIUS); }
  void SetSearchMethodToConeStep() { this->SetSearchMethod(CONE_STEP); }
  void SetSearchMethodToMaximumMipmap() { this->SetSearchMethod(MAXIMUM_MIPMAP); }
  void SetSearchMethodToAutomatic() { this->SetSearchMethod(AUTOMATIC); }
  void SetSearchMethodToRobustBinary() { this->SetSearchMethod(ROBUST_BINARY); }
  void SetSearchMethodToSlopeMipmap() { this->SetSearchMethod(SLOPE_MIPMAP); }
  const char* GetSearchMethodAsString();
  static const char* GetSearchMethodAsString(int method);
  ///@}

  /**
   * The method the last render searched with: SearchMethod, or LinearBinary when the
   * method's acceleration image could not be had or the frame cannot search with it.
   */
  vtkGetMacro(ActiveSearchMethod, int);

  ///@{
  /**
   * A precomputed acceleration image for the search method (optional port 2), made
   * from the same height map: the output of vtkSafetyRadiusFilter for SafetyRadius,
   * vtkConeStepMapFilter for ConeStep, vtkMaximumMipmapFilter for MaximumMipmap,
   * vtkSlopeMipmapFilter for SlopeMipmap; for Automatic, that of AutomaticAcceleration.
   * Without one the mapper builds what its method needs. An image that does not fit
   * the method or the map is reported, and the search falls back to LinearBinary.
   */
  void SetAccelerationConnection(vtkAlgorithmOutput* output);
  void SetAccelerationData(vtkImageData* image);
  vtkImageData* GetAcceleration();
  ///@}

  /**
   * A new instance of the filter that makes the acceleration image `method` reads
   * (vtkSafetyRadiusFilter, vtkConeStepMapFilter, vtkMaximumMipmapFilter or
   * vtkSlopeMipmapFilter), or nullptr for a method that reads none; for Automatic, its
   * default's (the cone map: over slopes ask for SLOPE_MIPMAP's). The caller owns it.
   */
  VTK_NEWINSTANCE static vtkReliefAccelerationFilter* NewAccelerationFilter(int method);

  ///@{
  /**
   * The error tolerance e of the safety radii the mapper builds for SafetyRadius and
   * RobustBinary (see
   * vtkSafetyRadiusFilter), in units of relief depth: 0 (default) is exact; e > 0 lets
   * the search step over the ray where it is at most e below the field. Values out of
   * [0, 1] (the whole depth) are clamped, with a warning. A precomputed acceleration
   * image carries its own e.
   */
  void SetSafetyRadiusTolerance(double tolerance);
  vtkGetMacro(SafetyRadiusTolerance, double);
  ///@}

  ///@{
  /**
   * The acceleration the Automatic search steps long straight runs over: ConeStep's cone
   * map (CONE_STEP, default: two bytes a texel, and the fastest frames measured on
   * llvmpipe) or SlopeMipmap's pyramid (SLOPE_MIPMAP: 30 to 64% fewer height samples at
   * 45 and 80 degrees and the same tolerance, for eight bytes a texel and more work a
   * sample, which pays where texture reads cost the most; Documentation/methods.md). Any
   * other value is refused with an error. A precomputed acceleration image (port 2) must
   * be the one it names. Changing it rebuilds the shader once; curved rays
   * (vtkOpenGLQuadricReliefMapper) read neither.
   */
  void SetAutomaticAcceleration(int method);
  vtkGetMacro(AutomaticAcceleration, int);
  void SetAutomaticAccelerationToConeStep() { this->SetAutomaticAcceleration(CONE_STEP); }
  void SetAutomaticAccelerationToSlopeMipmap() { this->SetAutomaticAcceleration(SLOPE_MIPMAP); }
  const char* GetAutomaticAccelerationAsString()
  {
    return GetSearchMethodAsString(this->AutomaticAcceleration);
  }
  ///@}

  ///@{
  /**
   * What the Automatic search may leave out, in pixels (default 0.5): its hit lies within
   * this distance on screen of the exact one, and relief whose whole depth spans less on
   * screen is not searched. 0 asks for an exact search everywhere. Values that are
   * negative, not finite or above 100 are clamped, with a warning. A uniform: changing it
   * rebuilds nothing.
   */
  void SetScreenTolerance(double pixels);
  vtkGetMacro(ScreenTolerance, double);
  ///@}

  ///@{
  /**
   * Steps of the linear search (1 to 512, default 10) and of the binary refinement
   * (0 to 32, default 5). Values out of range are clamped, with a warning.
   */
  void SetLinearSteps(int steps);
  vtkGetMacro(LinearSteps, int);
  void SetBinarySteps(int steps);
  vtkGetMacro(BinarySteps, int);
  ///@}

  ///@{
  /**
   * World depth of relief depth 1 (s_z). Default 0.05. A value that cannot be drawn (zero,
   * negative, not finite, or deeper than the actor is large) draws the mesh flat, with
   * one warning.
   */
  void SetDepthScale(double depthScale);
  vtkGetMacro(DepthScale, double);
  ///@}

  ///@{
  /**
   * Light the relief as each pixel's footprint is, not as the one point at its centre:
   * where a pixel spans more than a third of a texel, the rays through four points of it
   * are searched too and the lights' diffuse terms averaged over their hits' normals
   * (about 5 times the samples where it spans 0.7 texels or more). Off, the normal at
   * the hit alone lights the pixel: minified or oblique relief aliases, as point-sampled
   * geometry does. Colour and self-shadows are taken at the centre's hit; a normal map
   * given with the heights (UseInputNormals) is read filtered instead, without the
   * footprint's rays. Default on.
   */
  void SetFootprintShading(bool enabled);
  vtkGetMacro(FootprintShading, bool);
  vtkBooleanMacro(FootprintShading, bool);
  ///@}

  ///@{
  /// A second texture-space ray toward each light darkens relief in its own shadow. Default on.
  void SetSelfShadowing(bool enabled);
  vtkGetMacro(SelfShadowing, bool);
  vtkBooleanMacro(SelfShadowing, bool);
  ///@}

  ///@{
  /**
   * Write the hit's true depth (default on), so relief interpenetrates other actors.
   * Off: the polygon's depth, as plain texturing would.
   */
  void SetDepthCorrection(bool enabled);
  vtkGetMacro(DepthCorrection, bool);
  vtkBooleanMacro(DepthCorrection, bool);
  ///@}

  ///@{
  /**
   * Off (default): the mapper decides which faces carry relief, so that past an outline
   * carved by the relief lies what is behind the shape. Front faces always do. Back faces
   * of a closed mesh (vtkReliefSurfaceFilter::IsClosed) seen from outside its bounds are
   * not drawn, unless the actor is translucent or the mapper clips: they could only show
   * through carved outlines. Other back faces (the inside
   * of an open shell, a closed one seen from within) carry relief where the view ray
   * reaches them from inside the shape; the quadric frame leaves out those behind an
   * outline its front faces carve. On: every face carries relief wherever VTK draws it,
   * back faces as relief carved into their back (two-sided sheets). The actor's culling
   * properties apply either way.
   */
  void SetTwoSidedRelief(bool enabled);
  vtkGetMacro(TwoSidedRelief, bool);
  vtkBooleanMacro(TwoSidedRelief, bool);
  ///@}

  /// Whether the last render left out the back faces (a closed mesh seen from outside).
  vtkGetMacro(BackFacesLeftOut, bool);

  enum DisplayModes
  {
    SHADED = 0,
    SAMPLE_COUNT = 1
  };

  ///@{
  /**
   * Shaded (default), or SampleCount: each covered pixel's red channel is
   * min(255, height samples the pixel took) / 255, green and blue 0: its view ray's,
   * and with FootprintShading those of the four rays through it.
   */
  void SetDisplayMode(int mode);
  vtkGetMacro(DisplayMode, int);
  void SetDisplayModeToShaded() { this->SetDisplayMode(SHADED); }
  void SetDisplayModeToSampleCount() { this->SetDisplayMode(SAMPLE_COUNT); }
  ///@}

  ///@{
  /// The height map: any 2D image; see vtkReliefTextureFilter for how it is read.
  void SetHeightMapConnection(vtkAlgorithmOutput* output);
  void SetHeightMapData(vtkImageData* image);
  vtkImageData* GetHeightMap();
  ///@}

  /**
   * The filter that turns the height map into the relief texture, to configure it. Its
   * settings decide what is drawn; what is drawn is a copy the mapper shares with all
   * mappers of the same height map and settings in its window. Its output port, fed the
   * height map at each render, serves filters downstream (an acceleration filter) and
   * gives the relief texture to whoever calls its Update().
   */
  vtkReliefTextureFilter* GetReliefTextureFilter();

  /// The mesh as rendered: triangulated, with normals, tangents and texture scale.
  virtual vtkPolyData* GetReliefSurface();

  /**
   * GPU memory the relief's textures take, in bytes, as last uploaded by a render:
   * the 16-bit depth texture, an input normal map's mipmapped texture if the
   * relief texture filter uses one (UseInputNormals), and the active search method's
   * acceleration image. 0 before the first render and after ReleaseGraphicsResources().
   * Mappers drawing in one window share these textures when their height map is the
   * same data (and acceleration image, or method and setting) with the same relief
   * texture settings: each reports the shared bytes.
   */
  virtual vtkIdType GetTextureBytes();

  /**
   * GPU memory all the relief mappers' textures in `window` take, in bytes, each texture
   * shared by several mappers counted once.
   */
  static vtkIdType GetTextureBytesInUse(vtkRenderWindow* window);

  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * vtkPolyDataMapper's copy (input included) and, from a relief mapper, its relief
   * settings: the search and its options, depth, shading, display mode, the height map's
   * and acceleration image's connections and the relief texture filter's settings, and
   * those of the frame where both mappers have it.
   */
  void ShallowCopy(vtkAbstractMapper* mapper) override;

  /**
   * The relief settings of ShallowCopy() alone, leaving the input and VTK's mapper
   * settings as they are. Each setter modifies this mapper only where a value changes.
   */
  virtual void CopyReliefSettings(vtkOpenGLReliefMapper* source);

  /// The last change of what CopyReliefSettings() copies: this mapper's settings and its
  /// relief texture filter's (and the frame's filters', in subclasses).
  virtual vtkMTimeType GetReliefSettingsMTime();

  /**
   * The modification time, as for any VTK object; to the checks of
   * vtkOpenGLPolyDataMapper that rebuild shaders and buffers on any change, the time of
   * the last change that was not one of the relief's options (ModifiedShaderOptions).
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkOpenGLReliefMapper();
  ~vtkOpenGLReliefMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  /// The input's bounds, without points that are not finite: those are not drawn.
  void ComputeBounds() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* actor) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* actor) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override;
  bool GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* actor) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override;
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override;

  /**
   * Modified() for a relief option: a uniform, or a shader option that says so through
   * ShaderOptionsTime. VTK's own checks do not rebuild shaders or buffers for it.
   */
  void ModifiedShaderOptions();
  /// Brings the relief surface and texture up to date; false when relief cannot be drawn.
  bool UpdateRelief(vtkRenderer* ren);
  /**
   * DepthScale, or 0 (the relief drawn flat) where it cannot be drawn: not finite, not
   * positive, or deeper than the actor is large. Warns once per value.
   */
  double UsableDepthScale(vtkActor* actor);
  /// The mesh as drawn (CurrentInput): the tangent frame filter's output here.
  virtual bool UpdateReliefSurface();
  /// Brings the textures the search reads up to date: the relief texture here.
  virtual bool UpdateReliefTexture(vtkRenderer* ren);
  /// The image connected to input port `port` (1 or 2), or null.
  vtkImageData* GetImageOnPort(int port);
  /// Brings the search method's acceleration image up to date, or falls back.
  virtual void UpdateAcceleration(vtkRenderer* ren);
  /// Binds the search's textures to texture units for a render (true), frees them (false).
  virtual void ActivateReliefTextures(bool activate);
  /// The uniforms of the search's textures.
  virtual void SetReliefTextureParameters(vtkShaderProgram* program);
  /// The search's defines (RELIEF_SEARCH), before all relief code of the fragment shader.
  virtual std::string GetSearchDefines();
  /// The searches' GLSL (//VTK::Relief::Search).
  virtual std::string GetSearchSource();
  /// Code run after VTK's colours are set, before the lighting: none here.
  virtual std::string GetHitColourCode() { return ""; }
  void SetActiveSearchMethod(int method);
  /// The description of ActiveSearchMethod.
  const vtkReliefSearchMethod& GetActiveSearch();
  /// Binds the texture coordinates and the frame's arrays to the shader inputs (none
  /// when relief is not drawn).
  void MapReliefAttributes(bool relief);
  /// Binds the frame's own arrays (MapReliefAttribute): the tangent frame's here.
  virtual void MapFrameAttributes(bool relief);
  /// Whether this render leaves out back faces, which only carved outlines could show.
  bool ShouldCullBackFaces(vtkRenderer* ren, vtkActor* actor);
  ///@{
  /// Shader inputs of the frame, bound by name to the relief surface's point arrays.
  static constexpr const char* NormalAttribute = "reliefNormalMC";
  static constexpr const char* TangentAttribute = "reliefTangentMC";
  static constexpr const char* TCoordAttribute = "reliefTCoordMC";
  static constexpr const char* TextureScaleAttribute = "reliefTextureScaleMC";
  ///@}
  /// Binds one shader input to a point array of CurrentInput (unbinds it for nullptr).
  void MapReliefAttribute(const char* shaderInput, const char* arrayName);
  /**
   * How this mapper's frame searches with `method` (vtkReliefSearchMethod::Get here,
   * Automatic's over AutomaticAcceleration), or null where it cannot: then LinearBinary is
   * used.
   */
  virtual const vtkReliefSearchMethod* DescribeSearch(int method);
  /// Why DescribeSearch() refused, for the warning.
  virtual const char* GetUnsupportedSearchReason() { return ""; }
  /// The frame's GLSL (vtkReliefCommon.glsl's frame interface): the tangent frame here.
  virtual std::string GetFrameSource();
  /// Defines the frame's source reads, before all relief code of every stage: none here.
  virtual std::string GetFrameDefines();
  /// The frame's source for one shader stage (RELIEF_VERTEX_STAGE, ...).
  std::string GetFrameShaderCode(const char* stage);
  /// The tangent frame filter, made on first use.
  vtkReliefTangentFrameFilter* GetTangentFrameFilter();
  ///@{
  /// The relief's code at VTK's tags (vtkReliefShaderRewrites), each missing tag noted.
  void InsertReliefVertexShader(vtkShader* vertexShader);
  void InsertReliefFragmentShader(vtkShader* fragmentShader, int lightComplexity);
  void InsertReliefGeometryShader(vtkShader* geometryShader);
  void Insert(std::string& source, const char* tag, const std::string& code,
    bool (*insertion)(std::string&, const char*, const std::string&));
  void ReportMissingShaderTags();
  ///@}
  /**
   * Each light's diffuse term lit over the pixel's footprint (reliefDiffuse) and, but the
   * headlight's, weighted by the relief's self-shadow; or one warning why not.
   */
  void LightThroughRelief(std::string& fragmentSource, int lightComplexity, vtkActor* actor);

  int SearchMethod = AUTOMATIC;
  int AutomaticAcceleration = CONE_STEP;
  double ScreenTolerance = 0.5;
  int LinearSteps = 10;
  int BinarySteps = 5;
  double SafetyRadiusTolerance = 0.0;
  double DepthScale = 0.05;
  bool SelfShadowing = true;
  bool FootprintShading = true;
  bool CompiledFootprintShading = true; // the shader's, last built
  bool DepthCorrection = true;
  int DisplayMode = SHADED;
  bool TwoSidedRelief = false;

  vtkSmartPointer<vtkReliefTangentFrameFilter> TangentFrame; // GetTangentFrameFilter()
  vtkNew<vtkReliefTextureFilter> ReliefTextureFilter;
  vtkNew<vtkOpenGLReliefTextures> Textures; // on the GPU: relief and acceleration
  bool InputNormals = false; // the shader reads an input normal map (the textures' say)
  int ActiveSearchMethod = AUTOMATIC; // SearchMethod, or its fallback
  bool WarnedAccelerationFallback = false;
  bool WarnedUnsupportedSearchMethod = false;
  vtkTimeStamp ShaderOptionsTime; // the search, frame, input normals or relief on/off changed
  vtkMTimeType ShaderOptionsMTime = 0; // the modification time a relief option last gave
  vtkMTimeType OtherChangesMTime = 0;  // the last before it that was of another kind
  bool HidingShaderOptions = false;    // within VTK's rebuild checks
  bool DrawingRelief = false;
  bool SurfaceClosed = false; // of the surface drawn, as of SurfaceClosedTime
  vtkMTimeType SurfaceClosedTime = 0;
  vtkPolyData* SurfaceClosedMesh = nullptr; // compared by address only
  vtkPolyData* CheckedInput = nullptr; // the input ComputeBounds checked, by address only
  vtkMTimeType CheckedInputTime = 0;
  bool InputRefersToMissingPoints = false;
  bool BackFacesLeftOut = false; // the last render culled back faces (GL state saved)
  bool SavedCullFace = false;
  unsigned int SavedCullFaceMode = 0;
  bool WarnedMissingHeightMap = false;
  bool WarnedDepthScale = false;
  double DrawnDepthScale = 0.0; // what this render's shaders use: UsableDepthScale()
  double ReliefTopDepth = 0.0;  // the relief texture's shallowest depth, in [0, 1]
  bool WarnedUnmatchedLighting = false;
  std::vector<const char*> MissingShaderTags; // by the shader being built
  bool WarnedMissingShaderTags = false;
  bool WarnedTextureReads = false;

private:
  vtkOpenGLReliefMapper(const vtkOpenGLReliefMapper&) = delete;
  void operator=(const vtkOpenGLReliefMapper&) = delete;
};

#endif
