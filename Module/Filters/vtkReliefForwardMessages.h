/**
 * vtkReliefForwardMessages(source, owner): the errors and warnings of `source`, a filter
 * an algorithm runs inside itself, become the owner's. Observers of the owner receive
 * them; without observers they are printed as usual, as the owner's own messages would
 * be. Header only, not wrapped: a helper of the relief classes.
 */
#ifndef vtkReliefForwardMessages_h
#define vtkReliefForwardMessages_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"

inline void vtkReliefForwardMessages(vtkObject* source, vtkObject* owner)
{
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(owner);
  forward->SetCallback([](vtkObject*, unsigned long event, void* target, void* message) {
    auto* self = static_cast<vtkObject*>(target);
    if (self->HasObserver(event))
    {
      self->InvokeEvent(event, message);
    }
    else if (event == vtkCommand::ErrorEvent)
    {
      vtkOutputWindowDisplayErrorText(static_cast<const char*>(message));
    }
    else
    {
      vtkOutputWindowDisplayWarningText(static_cast<const char*>(message));
    }
  });
  source->AddObserver(vtkCommand::ErrorEvent, forward);
  source->AddObserver(vtkCommand::WarningEvent, forward);
}

#endif
