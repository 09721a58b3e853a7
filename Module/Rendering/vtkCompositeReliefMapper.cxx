#include "vtkCompositeReliefMapper.h"

#include "vtkCommand.h"
#include "vtkCompositeDataPipeline.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkOutputWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cstring>
#include <string>

vtkStandardNewMacro(vtkCompositeReliefMapper);

vtkCompositeReliefMapper::vtkCompositeReliefMapper()
  : ReliefMapper(vtkSmartPointer<vtkOpenGLReliefMapper>::New())
{
  this->BlockMessages->SetClientData(this);
  this->BlockMessages->SetCallback(&vtkCompositeReliefMapper::OnBlockMessage);
}

vtkCompositeReliefMapper::~vtkCompositeReliefMapper()
{
  // the superclass holds the current block mappers a little longer
  for (auto& mapper : this->BlockMappers)
  {
    this->StopObserving(mapper);
  }
}

void vtkCompositeReliefMapper::StopObserving(vtkOpenGLReliefMapper* mapper)
{
  mapper->RemoveObserver(this->BlockMessages); // observers others added stay
}

vtkMTimeType vtkCompositeReliefMapper::GetMTime()
{
  return this->vtkAbstractMapper::GetMTime();
}

void vtkCompositeReliefMapper::SetReliefMapper(vtkOpenGLReliefMapper* mapper)
{
  if (!mapper)
  {
    vtkErrorMacro("SetReliefMapper(nullptr): give a vtkOpenGLReliefMapper (or a subclass "
                  "for another frame) to make the blocks' mappers like; keeping "
      << this->ReliefMapper->GetClassName() << ".");
    return;
  }
  if (mapper != this->ReliefMapper)
  {
    this->ReliefMapper = mapper;
    this->Modified(); // the superclass remakes the block mappers
  }
}

vtkOpenGLReliefMapper* vtkCompositeReliefMapper::GetReliefMapper()
{
  return this->ReliefMapper;
}

int vtkCompositeReliefMapper::GetNumberOfBlockMappers()
{
  return static_cast<int>(this->BlockMappers.size());
}

vtkOpenGLReliefMapper* vtkCompositeReliefMapper::GetBlockMapper(int index)
{
  return index >= 0 && index < this->GetNumberOfBlockMappers() ? this->BlockMappers[index].Get()
                                                                : nullptr;
}

vtkPolyDataMapper* vtkCompositeReliefMapper::MakeAMapper()
{
  vtkOpenGLReliefMapper* mapper = this->ReliefMapper->NewInstance();
  mapper->vtkMapper::ShallowCopy(this);
  mapper->CopyReliefSettings(this->ReliefMapper);
  mapper->AddObserver(vtkCommand::WarningEvent, this->BlockMessages);
  mapper->AddObserver(vtkCommand::ErrorEvent, this->BlockMessages);
  this->BlockMappers.emplace_back(mapper);
  // the superclass registers it, then gives up the reference New() made
  return mapper;
}

void vtkCompositeReliefMapper::OnBlockMessage(
  vtkObject*, unsigned long event, void* client, void* message)
{
  auto* self = static_cast<vtkCompositeReliefMapper*>(client);
  const char* text = static_cast<const char*>(message);
  if (!text)
  {
    return;
  }
  // the first line says where in the code ("Warning: In file, line n"): blocks' messages
  // from one place differ only by their numbers and the mapper's address
  const std::string where(text, std::find(text, text + std::strlen(text), '\n'));
  if (!self->ReportedMessages.insert(where).second)
  {
    return;
  }
  if (self->HasObserver(event))
  {
    self->InvokeEvent(event, message);
  }
  else if (event == vtkCommand::ErrorEvent)
  {
    vtkOutputWindowDisplayErrorText(text);
  }
  else
  {
    vtkOutputWindowDisplayWarningText(text);
  }
}

void vtkCompositeReliefMapper::CopySettingsToBlocks()
{
  if (this->ReliefMapper->GetReliefSettingsMTime() <= this->SettingsCopyTime.GetMTime())
  {
    return;
  }
  for (auto& mapper : this->BlockMappers)
  {
    mapper->CopyReliefSettings(this->ReliefMapper);
  }
  this->SettingsCopyTime.Modified();
}

void vtkCompositeReliefMapper::KeepBlockMappersItReplaces()
{
  auto* executive = vtkCompositeDataPipeline::SafeDownCast(this->GetExecutive());
  if (executive && executive->GetPipelineMTime() > this->InternalMappersBuildTime.GetMTime())
  {
    for (auto& mapper : this->BlockMappers)
    {
      this->StopObserving(mapper);
      this->ReplacedBlockMappers.push_back(mapper);
    }
    this->BlockMappers.clear();
    this->ReportedMessages.clear();
  }
}

void vtkCompositeReliefMapper::ReleaseReplacedBlockMappers(vtkWindow* window)
{
  for (auto& mapper : this->ReplacedBlockMappers)
  {
    mapper->ReleaseGraphicsResources(window);
  }
  this->ReplacedBlockMappers.clear();
}

bool vtkCompositeReliefMapper::HasOpaqueGeometry()
{
  this->KeepBlockMappersItReplaces();
  return this->Superclass::HasOpaqueGeometry();
}

bool vtkCompositeReliefMapper::HasTranslucentPolygonalGeometry()
{
  this->KeepBlockMappersItReplaces();
  return this->Superclass::HasTranslucentPolygonalGeometry();
}

void vtkCompositeReliefMapper::Render(vtkRenderer* renderer, vtkActor* actor)
{
  this->KeepBlockMappersItReplaces();
  this->CopySettingsToBlocks();
  this->Superclass::Render(renderer, actor);
  // block mappers made in this render have this render's settings
  this->SettingsCopyTime.Modified();
  this->ReleaseReplacedBlockMappers(renderer->GetRenderWindow());
}

void vtkCompositeReliefMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->ReleaseReplacedBlockMappers(window);
}

void vtkCompositeReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReliefMapper: " << this->ReliefMapper->GetClassName() << "\n";
  this->ReliefMapper->PrintSelf(os, indent.GetNextIndent());
  os << indent << "BlockMappers: " << this->BlockMappers.size() << "\n";
}
