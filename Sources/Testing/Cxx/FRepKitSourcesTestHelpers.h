// Small helpers shared by the modules' tests: a failing CHECK that reports file:line, an observer
// that counts error and warning events (vtkTest::ErrorObserver keeps the text), and one that
// counts executions.
#ifndef FRepKitSourcesTestHelpers_h
#define FRepKitSourcesTestHelpers_h

#include "vtkCommand.h"
#include "vtkObject.h"

#include <iostream>
#include <string>

// Prints what failed and makes the test return 1 at the end (keeps checking after a failure).
#define FREPKIT_CHECK(failures, condition)                                                         \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl;      \
      ++(failures);                                                                                \
    }                                                                                              \
  } while (false)

namespace frepkit_test
{
/// Counts ErrorEvent and WarningEvent and keeps every message.
class EventCounter : public vtkCommand
{
public:
  static EventCounter* New() { return new EventCounter; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->Errors;
      this->ErrorText += text;
    }
    else if (event == vtkCommand::WarningEvent)
    {
      ++this->Warnings;
      this->WarningText += text;
    }
  }
  void Observe(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  void Clear()
  {
    this->Errors = this->Warnings = 0;
    this->ErrorText.clear();
    this->WarningText.clear();
  }
  int Errors = 0;
  int Warnings = 0;
  std::string ErrorText;
  std::string WarningText;
};

/// Updates `filter` (an FRep object filter observed by `events`) and tells whether the request
/// was refused as the filters refuse one: exactly one error containing `expected` and an empty
/// output; says what happened otherwise.
template <class Filter>
bool RefusedWithOneError(Filter* filter, EventCounter* events, const char* expected)
{
  events->Clear();
  filter->Update();
  const bool empty = !filter->GetOutput()->HasModel();
  const bool said = events->ErrorText.find(expected) != std::string::npos;
  if (!empty || events->Errors != 1 || !said)
  {
    std::cerr << "expected one error with '" << expected << "', got " << events->Errors << ": "
              << events->ErrorText << std::endl;
  }
  return empty && events->Errors == 1 && said;
}

/// Counts the executions (RequestData) of an algorithm: observe its EndEvent.
class ExecutionCounter : public vtkCommand
{
public:
  static ExecutionCounter* New() { return new ExecutionCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};
}

#endif
