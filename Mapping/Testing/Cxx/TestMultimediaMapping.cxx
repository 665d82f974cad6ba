// vtkMultimediaMapping: loads a mapping from JSON text and from a file, saves it and loads the
// saved file to the same specification, and reports every error of a bad file with its place
// through vtkErrorMacro while keeping the previous specification.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkMultimediaMapping.h"

#include "vtkNew.h"

#include <cstdio>
#include <fstream>
#include <string>

namespace
{

// Expected error text, printed so that ctest's "ERROR: " failure pattern does not match it.
std::string Quoted(std::string text)
{
  for (std::size_t at = text.find("ERROR:"); at != std::string::npos; at = text.find("ERROR:", at))
  {
    text.replace(at, 6, "(expected) error:");
  }
  return text;
}
}

int TestMultimediaMapping(int, char*[])
{
  int failures = 0;
  vtkNew<vtkMultimediaMapping> mapping;
  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(mapping);

  const std::string good = R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-1, 1] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-1, 1] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-1, 1] }],
      "x4": [{ "type": "dynamic", "range": [0, 1] },
             { "type": "audio", "parameter": "loudness", "target": [0.2, 0.8] }]
    },
    "animation": { "duration": 4, "fps": 12 }
  })";
  const vtkMTimeType before = mapping->GetMTime();
  FREPKIT_CHECK(failures, mapping->LoadJSON(good));
  FREPKIT_CHECK(failures, mapping->GetMTime() > before);
  FREPKIT_CHECK(failures, events->Errors == 0 && mapping->GetErrors().empty());
  FREPKIT_CHECK(failures, mapping->GetSpec().coordinates.size() == 4);
  FREPKIT_CHECK(failures, mapping->GetSpec().animation.duration == 4.0);
  FREPKIT_CHECK(failures, mapping->GetSpec().animation.fps == 12.0);

  // Save, load the file, same JSON.
  const std::string path = "TestMultimediaMapping.json";
  FREPKIT_CHECK(failures, mapping->SaveFile(path));
  vtkNew<vtkMultimediaMapping> copy;
  FREPKIT_CHECK(failures, copy->LoadFile(path));
  FREPKIT_CHECK(failures, copy->ToJSON() == mapping->ToJSON());
  std::remove(path.c_str());

  // A bad file: every error with its place, the previous specification kept.
  const std::string bad = R"({
    "coordinates": {
      "x1": [{ "type": "wrld", "axis": "x" }],
      "x2": [{ "type": "world", "axis": "y", "range": [1, 1] }]
    },
    "animation": { "fps": 0 }
  })";
  FREPKIT_CHECK(failures, !mapping->LoadJSON(bad, "bad.json"));
  std::cout << "expected errors:\n" << Quoted(events->ErrorText) << "\n";
  FREPKIT_CHECK(failures, events->Errors >= 3);
  FREPKIT_CHECK(failures, mapping->GetErrors().size() == static_cast<std::size_t>(events->Errors));
  FREPKIT_CHECK(
    failures, events->ErrorText.find("bad.json: coordinates.x1[0].type") != std::string::npos);
  FREPKIT_CHECK(failures, events->ErrorText.find("coordinates.x2[0].range") != std::string::npos);
  FREPKIT_CHECK(failures, events->ErrorText.find("animation.fps") != std::string::npos);
  FREPKIT_CHECK(failures, mapping->GetSpec().coordinates.size() == 4);

  // A file that does not exist, and a JSON syntax error with its line.
  events->Clear();
  FREPKIT_CHECK(failures, !mapping->LoadFile("no-such-mapping.json"));
  FREPKIT_CHECK(failures, events->Errors == 1);
  FREPKIT_CHECK(failures, events->ErrorText.find("no-such-mapping.json") != std::string::npos);
  events->Clear();
  FREPKIT_CHECK(failures, !mapping->LoadJSON("{\n  \"coordinates\": {\n  ,\n}", "syntax.json"));
  std::cout << "expected syntax error: " << Quoted(events->ErrorText) << "\n";
  FREPKIT_CHECK(failures, events->ErrorText.find("syntax.json") != std::string::npos);
  FREPKIT_CHECK(failures, events->ErrorText.find("3") != std::string::npos); // line 3

  mapping->Print(std::cout);
  return failures == 0 ? 0 : 1;
}
