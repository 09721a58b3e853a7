/**
 * @class   vtkReliefSurfaceRepresentation
 * @brief   ParaView's "Relief Surface": the Surface representation drawn with relief
 *
 * ParaView's Surface representation (vtkGeometryRepresentationWithFaces) whose mapper is
 * a vtkCompositeReliefMapper: every block of the delivered data is drawn by a relief mapper
 * of the chosen frame, with the height map, depth and search set here. Colouring, the
 * colour texture, lighting and the other Surface properties work as for Surface. The
 * relief fragments write their true depth, so ParaView's compositing across MPI ranks
 * (IceT) orders them with everything else. While ParaView interacts with a level of
 * detail (large data), the decimated surface is drawn plainly. What Surface sets only on
 * vtkCompositePolyDataMapper2 does not reach the relief: per-block colour, opacity and
 * visibility, seamless texture coordinates, and the selection's id arrays (cells are
 * picked by the relief mapper's own ids, blocks are not told apart).
 *
 * Without a height map it draws the plain surface, and the relief mapper says, once,
 * what to set (a colour texture's luminance is no height: mortar, lighter than bricks,
 * would stand out of the wall). The mappers' messages go to ParaView's output window.
 */
#ifndef vtkReliefSurfaceRepresentation_h
#define vtkReliefSurfaceRepresentation_h

#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkReliefParaViewRepresentationsModule.h" // For export macro
#include "vtkSmartPointer.h"                        // For HeightMap

class vtkCompositeReliefMapper;
class vtkTexture;

class VTKRELIEFPARAVIEWREPRESENTATIONS_EXPORT vtkReliefSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkReliefSurfaceRepresentation* New();
  vtkTypeMacro(vtkReliefSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Frames
  {
    TANGENT = 0,   ///< vtkOpenGLReliefMapper: per-vertex tangent frame, flat below each polygon
    QUADRIC = 1,   ///< vtkOpenGLQuadricReliefMapper: curved surfaces, carved outlines
    DERIVATIVE = 2 ///< vtkOpenGLDerivativeReliefMapper: frame from screen derivatives
  };

  ///@{
  /// The frame, and so the relief mapper's class (default TANGENT).
  void SetReliefFrame(int frame);
  vtkGetMacro(ReliefFrame, int);
  ///@}

  ///@{
  /**
   * The height map: the image a texture proxy reads (a file, or a pipeline's image
   * data). Null: no relief.
   */
  void SetReliefHeightMap(vtkTexture* texture);
  vtkTexture* GetReliefHeightMap();
  ///@}

  ///@{
  /// vtkOpenGLReliefMapper's settings, forwarded.
  void SetReliefDepthScale(double depth);
  void SetReliefSearchMethod(int method);
  void SetReliefScreenTolerance(double pixels);
  void SetReliefAutomaticAcceleration(int method);
  void SetReliefSafetyRadiusTolerance(double tolerance);
  void SetReliefSelfShadowing(bool enabled);
  ///@}

  /// vtkReliefTextureFilter's InputConvention: bright is high (0) or deep (1).
  void SetReliefHeightConvention(int convention);

  /// The mapper drawing the relief, for the settings not forwarded here.
  vtkCompositeReliefMapper* GetReliefMapper();

  /**
   * Surface's names the selection's id arrays on vtkCompositePolyDataMapper2, which this
   * representation does not draw with (ParaView's views call it around every selection,
   * on every representation): nothing to do.
   */
  void SetArrayIdNames(const char* pointArray, const char* cellArray) override;

  /// Surface's, and at each render the height map's current image: the texture's input
  /// may be set or changed after the texture was given (a pipeline Texture proxy, a state).
  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inputInformation,
    vtkInformation* outputInformation) override;

protected:
  vtkReliefSurfaceRepresentation();
  ~vtkReliefSurfaceRepresentation() override;

  /// The relief mapper's height map: the height map texture's input, if any.
  void ConnectHeightMap();

  int ReliefFrame = TANGENT;
  vtkSmartPointer<vtkTexture> HeightMap;

private:
  vtkReliefSurfaceRepresentation(const vtkReliefSurfaceRepresentation&) = delete;
  void operator=(const vtkReliefSurfaceRepresentation&) = delete;
};

#endif
