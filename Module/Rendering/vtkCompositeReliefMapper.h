/**
 * @class   vtkCompositeReliefMapper
 * @brief   draws every polygonal block of a composite dataset with relief
 *
 * A vtkCompositePolyDataMapper whose block mappers are relief mappers made like
 * GetReliefMapper(): of its class (the frame: vtkOpenGLReliefMapper,
 * vtkOpenGLQuadricReliefMapper or vtkOpenGLDerivativeReliefMapper) and with its relief
 * settings and height map (vtkOpenGLReliefMapper::CopyReliefSettings). Configure that
 * mapper; it is never drawn itself. A change of its settings reaches the block mappers at
 * the next render without rebuilding them (a uniform stays a uniform); a new input, or
 * SetReliefMapper(), makes new block mappers, and the GPU resources of the ones they
 * replace are released at the next render. The blocks of one height map share its
 * textures (one copy per window). A plain vtkPolyData input is drawn as one block.
 *
 * This is the mapper ParaView's "Relief Surface" representation draws with, since
 * ParaView hands its mappers multiblock datasets; in VTK it draws the output of
 * multiblock pipelines. The block mappers' warnings and errors are this mapper's, each
 * reported once per set of block mappers rather than once per block (messages from one
 * line of the code count as one, whatever numbers they hold).
 */
#ifndef vtkCompositeReliefMapper_h
#define vtkCompositeReliefMapper_h

#include "vtkCallbackCommand.h" // For BlockMessages
#include "vtkCompositePolyDataMapper.h"
#include "vtkNew.h" // For BlockMessages
#include "vtkReliefRenderingModule.h" // For export macro
#include "vtkSmartPointer.h"          // For ReliefMapper

#include <set>    // For ReportedMessages
#include <string> // For ReportedMessages
#include <vector> // For BlockMappers

class vtkOpenGLReliefMapper;

class VTKRELIEFRENDERING_EXPORT vtkCompositeReliefMapper : public vtkCompositePolyDataMapper
{
public:
  static vtkCompositeReliefMapper* New();
  vtkTypeMacro(vtkCompositeReliefMapper, vtkCompositePolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The mapper every block's mapper is made like (default: a vtkOpenGLReliefMapper, the
   * tangent frame). Setting another, of another class for another frame, remakes the
   * block mappers; null is refused with an error.
   */
  void SetReliefMapper(vtkOpenGLReliefMapper* mapper);
  vtkOpenGLReliefMapper* GetReliefMapper();
  ///@}

  ///@{
  /// The block mappers of the last render, in the order of the input's polygonal blocks.
  int GetNumberOfBlockMappers();
  vtkOpenGLReliefMapper* GetBlockMapper(int index);
  ///@}

  void Render(vtkRenderer* renderer, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  bool HasOpaqueGeometry() override;
  bool HasTranslucentPolygonalGeometry() override;

  /**
   * The superclass remakes every block mapper when this time passes their making: it
   * leaves out the lookup table's, which each render passes to the blocks, so that a
   * colour map's edit does not remake them (their frames, buffers and shaders).
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkCompositeReliefMapper();
  ~vtkCompositeReliefMapper() override;

  /// A mapper of GetReliefMapper()'s class and settings, with this mapper's VTK settings.
  vtkPolyDataMapper* MakeAMapper() override;

  /// The block mappers' settings brought up to GetReliefMapper()'s.
  void CopySettingsToBlocks();

  /**
   * Where the superclass is about to make new block mappers (its input or this mapper
   * changed), the current ones are kept until ReleaseReplacedBlockMappers() can release
   * their GPU resources with the window.
   */
  void KeepBlockMappersItReplaces();
  void ReleaseReplacedBlockMappers(vtkWindow* window);

  /// A block mapper's message, passed on unless one from the same line of code was.
  static void OnBlockMessage(vtkObject* caller, unsigned long event, void* self, void* message);
  void StopObserving(vtkOpenGLReliefMapper* mapper);

  vtkSmartPointer<vtkOpenGLReliefMapper> ReliefMapper;
  std::vector<vtkSmartPointer<vtkOpenGLReliefMapper>> BlockMappers; // as the superclass's
  std::vector<vtkSmartPointer<vtkOpenGLReliefMapper>> ReplacedBlockMappers;
  vtkNew<vtkCallbackCommand> BlockMessages; // observes every block mapper
  vtkTimeStamp SettingsCopyTime;
  std::set<std::string> ReportedMessages; // since the block mappers were last made

private:
  vtkCompositeReliefMapper(const vtkCompositeReliefMapper&) = delete;
  void operator=(const vtkCompositeReliefMapper&) = delete;
};

#endif
