#ifndef ReliefEventRecorder_h
#define ReliefEventRecorder_h

#include "vtkCommand.h"

#include <string>
#include <vector>

// Records the events it observes and the text VTK passes with error and
// warning events. Observing ErrorEvent and WarningEvent also keeps VTK from
// printing them, so expected failures leave the test log clean.
class ReliefEventRecorder : public vtkCommand
{
public:
  static ReliefEventRecorder* New() { return new ReliefEventRecorder; }

  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    this->Events.push_back(event);
    if (event == vtkCommand::ProgressEvent && callData)
    {
      this->Progress.push_back(*static_cast<double*>(callData));
    }
    else if (callData)
    {
      this->Messages.emplace_back(static_cast<const char*>(callData));
    }
  }

  int Count(unsigned long event) const
  {
    int count = 0;
    for (unsigned long seen : this->Events)
    {
      count += seen == event ? 1 : 0;
    }
    return count;
  }

  bool AnyMessageContains(const std::string& text) const
  {
    for (const std::string& message : this->Messages)
    {
      if (message.find(text) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }

  void Clear()
  {
    this->Events.clear();
    this->Messages.clear();
    this->Progress.clear();
  }

  std::vector<unsigned long> Events;
  std::vector<std::string> Messages;
  std::vector<double> Progress;
};

#endif
