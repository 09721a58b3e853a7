/**
 * @class   vtkOpenGLReliefImpostorMapper
 * @brief   draws a mesh as a relief impostor: height fields searched inside its box
 *
 * A relief impostor (Baboud and Decoret 2006, s4) replaces a whole object by the height
 * fields vtkReliefImpostorFilter captures around it: the mapper draws the twelve
 * triangles of the object's box, and each pixel follows its view ray through the box into
 * every view, searched by one of the relief search methods, to the first point every
 * view's field holds inside the object (vtkReliefImpostorFrame.glsl). That point is lit
 * with the captured normal and colour of the view that sees it most squarely, by the
 * renderer's lights and the actor's property as VTK's mapper lights the mesh (the mesh's
 * scalars colour it through this mapper's lookup table; without scalars, the property's
 * colour does), and its true depth is written, so the impostor interpenetrates the rest
 * of the scene as the mesh would. A frame costs the pixels the object covers, not its triangles: a
 * field of a thousand copies of a detailed part draws at the cost of its textures.
 *
 * Port 0 takes the mesh. The mapper captures it with its own vtkReliefImpostorFilter
 * (GetImpostorFilter() to set views, projection, resolutions, a colour texture), once per
 * change of the mesh or of those settings, at the resolution the impostor's size on
 * screen needs (AutomaticResolution); the mapper's bounds are the capture's box. Many
 * actors may share one mapper, each with its own matrix and property: the textures are
 * made and uploaded once, colours compressed (CompressColours), so a field of small
 * instances holds a few hundred kilobytes however many triangles the mesh has.
 *
 * Where the impostor cannot be made (the capture failed: see its error; or its textures
 * exceed this OpenGL's limits) the mesh itself is drawn, with one warning, so no data is
 * lost from view. Points, wireframe and edges are drawn from the mesh too, as VTK's
 * mapper draws them.
 */
#ifndef vtkOpenGLReliefImpostorMapper_h
#define vtkOpenGLReliefImpostorMapper_h

#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkReliefRenderingModule.h" // For export macro

#include <string> // For ColouredKey

class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkReliefArrayTexture;
class vtkReliefImpostorFilter;
class vtkReliefSearchMethod;

class VTKRELIEFRENDERING_EXPORT vtkOpenGLReliefImpostorMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkOpenGLReliefImpostorMapper* New();
  vtkTypeMacro(vtkOpenGLReliefImpostorMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The filter that captures the mesh, to configure it (views, projection, resolutions:
  /// setting those turns AutomaticResolution off).
  vtkReliefImpostorFilter* GetImpostorFilter();

  ///@{
  /**
   * How each view's field is searched, one of vtkOpenGLReliefMapper::SearchMethods:
   * - Automatic (default) and MaximumMipmap: the exact pyramid search (Tevs et al. 2008),
   *   a pyramid per view built with the capture; about log n steps a view.
   * - ExactDDA: every cell the ray crosses, exact.
   * - Linear, LinearBinary, Secant: LinearSteps fixed steps through the box, then
   *   BinarySteps of refinement; features thinner than a step are missed.
   * ConeStep, SafetyRadius, RobustBinary and SlopeMipmap step only along rays that
   * descend into a field; behind the object the views' rays rise, so they search with
   * MaximumMipmap, with a warning. Changing the method rebuilds the shader once.
   */
  void SetSearchMethod(int method);
  vtkGetMacro(SearchMethod, int);
  ///@}

  /// The method the last render searched with (SearchMethod, or MaximumMipmap instead).
  vtkGetMacro(ActiveSearchMethod, int);

  ///@{
  /**
   * Steps of the fixed-step searches through the whole box (1 to 4096, default 64) and of
   * their refinement (0 to 32, default 8). Values out of range are clamped, with a warning.
   */
  void SetLinearSteps(int steps);
  vtkGetMacro(LinearSteps, int);
  void SetBinarySteps(int steps);
  vtkGetMacro(BinarySteps, int);
  ///@}

  ///@{
  /**
   * Off (default): each pixel writes the depth of its hit, so other actors interpenetrate
   * the impostor exactly; the box's back faces are drawn, and a camera inside the box
   * still sees the object. On: the box's front faces are drawn and their depth kept, a
   * conservative depth (s4.4) the GPU may test before shading; what lies inside the box
   * but in front of the object is hidden by it. A camera inside the box (or whose near
   * plane reaches into it) cannot see the front faces: that render writes true depth
   * instead, with one warning a setting.
   */
  void SetConservativeDepth(bool conservative);
  vtkGetMacro(ConservativeDepth, bool);
  vtkBooleanMacro(ConservativeDepth, bool);
  ///@}

  ///@{
  /**
   * On (default): the capture's resolutions follow the impostor's size on screen. Its
   * depth texels per view side are the power of two at or above the most pixels its box
   * has spanned in any render (at least MinimumAutomaticResolution, at most
   * MaximumAutomaticResolution), its colour texels twice as many; they are raised, and the
   * mesh captured again, only when the impostor is drawn larger than its capture resolves.
   * A field of small instances thus holds small textures, and a close-up sharp ones (the
   * first frame of actors at many distances may capture once per power of two). Shadow
   * maps' renders do not count. Off: the filter's resolutions are kept as set. Setting the
   * filter's DepthResolution or ColourResolution yourself, to other values than this
   * mapper last gave them, turns it off; to pin the resolution this mapper chose, turn it
   * off.
   */
  void SetAutomaticResolution(bool automatic);
  vtkGetMacro(AutomaticResolution, bool);
  vtkBooleanMacro(AutomaticResolution, bool);
  ///@}
  static constexpr int MinimumAutomaticResolution = 64;
  static constexpr int MaximumAutomaticResolution = 512;

  ///@{
  /**
   * On (default): the colours are held compressed where the GL can (S3TC DXT1: half a
   * byte a texel, an eighth of 8-bit RGBA), compressed by the GL on upload. Off, or where
   * the GL has no S3TC: 8-bit RGBA. Normals are held as two signed bytes (octahedral)
   * either way.
   */
  void SetCompressColours(bool compress);
  vtkGetMacro(CompressColours, bool);
  vtkBooleanMacro(CompressColours, bool);
  ///@}

  enum DisplayModes
  {
    SHADED = 0,
    SAMPLE_COUNT = 1
  };

  ///@{
  /**
   * Shaded (default), or SampleCount: each covered pixel's red channel is
   * min(255, height samples its ray took) / 255, green and blue 0.
   */
  vtkSetClampMacro(DisplayMode, int, SHADED, SAMPLE_COUNT);
  vtkGetMacro(DisplayMode, int);
  void SetDisplayModeToShaded() { this->SetDisplayMode(SHADED); }
  void SetDisplayModeToSampleCount() { this->SetDisplayMode(SAMPLE_COUNT); }
  ///@}

  /// Whether the last render drew the impostor (false: the mesh itself, or nothing).
  vtkGetMacro(DrawingImpostor, bool);

  /**
   * GPU bytes of the impostor's textures as last uploaded (depths, the search's pyramids,
   * colours and normals with their mipmaps); 0 before the first render and after release.
   */
  vtkIdType GetTextureBytes();

  void ReleaseGraphicsResources(vtkWindow* window) override;
  void RenderPiece(vtkRenderer* ren, vtkActor* actor) override;
  /// The capture's box (the mesh's bounds, padded as the filter pads them).
  void ComputeBounds() override;

protected:
  vtkOpenGLReliefImpostorMapper();
  ~vtkOpenGLReliefImpostorMapper() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* actor) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* actor) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override;
  void SetMapperShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override;
  void SetCameraShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override;

  /**
   * The mesh with the colours VTK's mapper would give its points (this mapper's lookup
   * table, scalar range and array), white where it has none and the capture reads no
   * colour texture; made again only when one of those changes.
   */
  vtkPolyData* ColouredMesh(vtkPolyData* mesh);
  /// Captures the mesh and uploads the textures where they are out of date; false when
  /// the impostor cannot be drawn (said once).
  bool UpdateImpostor(vtkRenderer* ren, vtkActor* actor);
  /// AutomaticResolution: raises the capture's resolutions to what `actor` needs on screen.
  void FollowScreenSize(vtkRenderer* ren, vtkActor* actor);
  /// Gives the filter `depthResolution` and twice it for colour, as AutomaticResolution.
  void ApplyResolution(int depthResolution);
  /// Whether `actor` is drawn into a shadow map (vtkShadowMapBakerPass).
  static bool BakingShadows(vtkActor* actor);
  /// The most pixels across that the box of `actor` spans in `ren`'s viewport.
  static double ScreenSpan(const double bounds[6], vtkRenderer* ren, vtkActor* actor);
  /// The capture's textures on the GPU of `window`; false where one cannot be made.
  bool UploadTextures(vtkOpenGLRenderWindow* window);
  void ReleaseTextures(vtkWindow* window);
  /// Says once that the mesh is empty.
  void WarnEmptyMesh();
  /// Says once why the mesh is drawn instead of the impostor; false.
  bool WarnFallback(const char* why);
  /// The box's depth along view `view` over the size of its face.
  double GetDepthRatio(int view);
  /// The box's twelve triangles, drawn in place of the mesh.
  void MakeBox();
  /// Whether this render draws the box's back faces and writes true depth.
  bool ShouldWriteDepth(vtkRenderer* ren, vtkActor* actor);
  const vtkReliefSearchMethod& GetActiveSearch();
  /// The method `method` searches the impostor with.
  static int ImpostorSearchMethod(int method);

  int SearchMethod = 7; // vtkOpenGLReliefMapper::AUTOMATIC
  int ActiveSearchMethod = 6; // vtkOpenGLReliefMapper::MAXIMUM_MIPMAP
  int LinearSteps = 64;
  int BinarySteps = 8;
  bool ConservativeDepth = false;
  bool AutomaticResolution = true;
  bool CompressColours = true;
  int DisplayMode = SHADED;
  int AppliedDepthResolution = 0; // AutomaticResolution's for the filter; colour twice it

  vtkNew<vtkReliefImpostorFilter> ImpostorFilter;
  vtkNew<vtkPolyData> Box; // drawn in place of the mesh
  vtkNew<vtkPolyData> Coloured; // the mesh as captured: ColouredMesh()
  std::string ColouredKey;      // what Coloured was made from
  bool ScalarColours = false;   // its colours are the mesh's scalars', not white
  vtkNew<vtkReliefArrayTexture> DepthTexture;
  vtkNew<vtkReliefArrayTexture> PyramidTexture;
  vtkNew<vtkReliefArrayTexture> ColourTexture;
  vtkNew<vtkReliefArrayTexture> NormalTexture;
  vtkMTimeType UploadedCaptureTime = 0; // the capture the textures hold
  vtkWindow* UploadedWindow = nullptr;   // where they are, compared by address only
  bool UploadedPyramid = false;         // the search's pyramid is among them
  vtkMTimeType FailedCaptureTime = 0;   // the capture whose textures could not be made,
  vtkWindow* FailedWindow = nullptr;    // where (by address only),
  bool FailedPyramid = false;           // and with or without the pyramid
  int Views = 0;                         // of the capture drawn
  int DepthSize = 0;
  int ColourSize = 0;
  double CaptureBox[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  double Projections[6][16] = {};       // row major, model to (u w, v w, depth w, w)
  bool DrawingImpostor = false;
  bool WritingDepth = true;             // this render: back faces and true depth
  bool SavedCullFace = false;
  vtkTypeBool SavedScalarVisibility = true; // the user's, while the box is drawn
  unsigned int SavedCullFaceMode = 0;
  bool WarnedFallback = false;
  bool WarnedEmptyMesh = false;
  bool WarnedSearchMethod = false;
  bool WarnedCameraInside = false;
  bool WarnedShaderTags = false;
  vtkTimeStamp ShaderOptionsTime; // the search method, views or drawing mode changed

private:
  vtkOpenGLReliefImpostorMapper(const vtkOpenGLReliefImpostorMapper&) = delete;
  void operator=(const vtkOpenGLReliefImpostorMapper&) = delete;
};

#endif
