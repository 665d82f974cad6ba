#include "vtkMultimediaMapping.h"

#include "Durable/atomic_output.h"
#include "Mapping/mapping_json.h"

#include "vtkObjectFactory.h"

#include <fstream>
#include <sstream>

vtkStandardNewMacro(vtkMultimediaMapping);

vtkMultimediaMapping::vtkMultimediaMapping() = default;
vtkMultimediaMapping::~vtkMultimediaMapping() = default;

bool vtkMultimediaMapping::LoadFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    this->Errors = { path + ": cannot open the mapping file" };
    vtkErrorMacro(<< this->Errors.front());
    return false;
  }
  std::stringstream text;
  text << in.rdbuf();
  return this->LoadJSON(text.str(), path);
}

bool vtkMultimediaMapping::LoadJSON(const std::string& text, const std::string& sourceName)
{
  const frep::mapping::LoadResult loaded = frep::mapping::load_mapping(text);
  this->Errors.clear();
  for (const auto& e : loaded.errors)
  {
    this->Errors.push_back(sourceName + ": " + (e.place.empty() ? "" : e.place + ": ") + e.message);
    vtkErrorMacro(<< this->Errors.back());
  }
  if (!this->Errors.empty())
  {
    return false;
  }
  this->Spec = loaded.spec;
  this->Modified();
  return true;
}

std::string vtkMultimediaMapping::ToJSON() const
{
  return frep::mapping::save_mapping(this->Spec);
}

bool vtkMultimediaMapping::SaveFile(const std::string& path) const
{
  // As every writer of the project: the one temporary beside the file, the data on disk before
  // the file gets its name, the name on disk before we report success (FRepKit::Durable).
  try
  {
    frep::durable::AtomicOutput out(path);
    out.stream() << this->ToJSON();
    out.commit();
    return true;
  }
  catch (const frep::durable::OutputError& e)
  {
    vtkErrorMacro(<< "cannot write the mapping file: " << e.what());
    return false;
  }
}

void vtkMultimediaMapping::SetSpec(const frep::mapping::Spec& spec)
{
  this->Spec = spec;
  this->Errors.clear();
  this->Modified();
}

void vtkMultimediaMapping::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Coordinates:";
  for (const auto& c : this->Spec.coordinates)
  {
    os << " " << c.name << " (" << c.channels.size() << " channels)";
  }
  os << "\n";
  os << indent << "Animation: " << this->Spec.animation.duration << " s at "
     << this->Spec.animation.fps << " fps" << (this->Spec.animation.path ? ", with a path" : "")
     << "\n";
  os << indent << "Render: " << this->Spec.render.width << " x " << this->Spec.render.height
     << "\n";
  os << indent << "Errors: " << this->Errors.size() << "\n";
}
