#include "vtkFRepMetamorphosis.h"

#include "vtkObjectFactory.h"

#include "Compiler/load_model.h"
#include "Morph/morph_text.h"

vtkStandardNewMacro(vtkFRepMetamorphosis);

//------------------------------------------------------------------------------
vtkFRepMetamorphosis::vtkFRepMetamorphosis() = default;

//------------------------------------------------------------------------------
vtkFRepMetamorphosis::~vtkFRepMetamorphosis() = default;

//------------------------------------------------------------------------------
void vtkFRepMetamorphosis::AddKey(const char* file, const char* object)
{
  this->KeyFiles.emplace_back(file ? file : "");
  this->KeyObjects.emplace_back(object ? object : "");
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkFRepMetamorphosis::RemoveAllKeys()
{
  if (!this->KeyFiles.empty())
  {
    this->KeyFiles.clear();
    this->KeyObjects.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkFRepMetamorphosis::AddLatticeAxis(int nodes)
{
  this->Lattice.push_back(nodes);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkFRepMetamorphosis::RemoveAllLatticeAxes()
{
  if (!this->Lattice.empty())
  {
    this->Lattice.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkFRepMetamorphosis::AddKeyWeight(const char* key, const char* expression)
{
  this->KeyWeights.emplace_back(key ? key : "", expression ? expression : "");
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkFRepMetamorphosis::RemoveAllKeyWeights()
{
  if (!this->KeyWeights.empty())
  {
    this->KeyWeights.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkFRepMetamorphosis::ReadProgramText(std::string& text, std::string& sourceName)
{
  frep::morph::MorphSpec spec;
  for (std::size_t i = 0; i < this->KeyFiles.size(); ++i)
  {
    spec.keys.push_back({ this->KeyFiles[i], this->KeyObjects[i] });
  }
  spec.lattice = this->Lattice;
  if (spec.lattice.empty())
  {
    spec.lattice = { static_cast<int>(spec.keys.size()) };
  }
  spec.scheme = this->Scheme == CATMULL_ROM ? frep::morph::Interpolation::CatmullRom
                : this->Scheme == B_SPLINE  ? frep::morph::Interpolation::BSpline
                                            : frep::morph::Interpolation::Linear;
  spec.alignment = this->Alignment == ALIGN_CENTROID ? frep::morph::Alignment::Centroid
                   : this->Alignment == ALIGN_SIZE   ? frep::morph::Alignment::CentroidAndSize
                                                     : frep::morph::Alignment::None;
  spec.normalisation = this->Normalisation == NORMALISE_DISTANCE
                         ? frep::morph::Normalisation::Distance
                         : frep::morph::Normalisation::None;
  constexpr frep::morph::TimingCurve curves[] = { frep::morph::TimingCurve::Linear,
    frep::morph::TimingCurve::Ease,
    frep::morph::TimingCurve::EaseIn,
    frep::morph::TimingCurve::EaseOut,
    frep::morph::TimingCurve::Hold };
  spec.timing = { curves[this->Timing], this->HoldFraction };
  for (const auto& [key, expression] : this->KeyWeights)
  {
    spec.key_weights.push_back({ key, expression });
  }
  frep::LoadOptions keyOptions;
  if (!this->Superclass::AddUserFunctions(keyOptions))
  {
    return false;
  }
  const frep::morph::MorphText morph =
    frep::morph::write_morph(spec, frep::morph::KeyPlacement::Pasted, keyOptions);
  if (!morph.ok())
  {
    for (const frep::Diagnostic& d : morph.diagnostics)
    {
      vtkErrorMacro(<< d.format());
    }
    return false;
  }
  // The parameters' coordinates are over [0, 1] unless SetCoordinateRange gave them another
  // interval (set here without Modified(): it is what the output's information will say).
  for (int i = morph.x_dim - static_cast<int>(spec.lattice.size()); i < morph.x_dim; ++i)
  {
    const std::size_t index = static_cast<std::size_t>(i);
    if (index >= this->HasCoordinateRange.size())
    {
      this->HasCoordinateRange.resize(index + 1, false);
      this->CoordinateRanges.resize(index + 1, { 0.0, 0.0 });
    }
    if (!this->HasCoordinateRange[index])
    {
      this->HasCoordinateRange[index] = true;
      this->CoordinateRanges[index] = { 0.0, 1.0 };
    }
  }
  this->Distances = morph.functions;
  text = morph.text;
  sourceName = "<metamorphosis>";
  return true;
}

//------------------------------------------------------------------------------
bool vtkFRepMetamorphosis::AddUserFunctions(frep::LoadOptions& options)
{
  if (!this->Superclass::AddUserFunctions(options))
  {
    return false;
  }
  if (!this->Distances || this->Distances->empty())
  {
    return true;
  }
  auto merged = std::make_shared<frep::UserFunctionRegistry>();
  for (const auto& registry : { options.functions, this->Distances })
  {
    const std::string e = registry ? merged->merge(*registry) : std::string();
    if (!e.empty())
    {
      vtkErrorMacro(<< "the keys' distances: " << e);
      return false;
    }
  }
  options.functions = std::move(merged);
  return true;
}

//------------------------------------------------------------------------------
void vtkFRepMetamorphosis::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Keys (" << this->KeyFiles.size() << "):";
  for (std::size_t i = 0; i < this->KeyFiles.size(); ++i)
  {
    os << " " << this->KeyFiles[i] << (this->KeyObjects[i].empty() ? "" : ":")
       << this->KeyObjects[i];
  }
  os << "\n" << indent << "Lattice:";
  for (const int n : this->Lattice)
  {
    os << " " << n;
  }
  os << (this->Lattice.empty() ? " (one axis of every key)" : "") << "\n";
  os << indent << "Scheme: " << this->Scheme << "\n";
  os << indent << "Alignment: " << this->Alignment << "\n";
  os << indent << "Normalisation: " << this->Normalisation << "\n";
  os << indent << "Timing: " << this->Timing << "\n";
  os << indent << "HoldFraction: " << this->HoldFraction << "\n";
  os << indent << "KeyWeights (" << this->KeyWeights.size() << "):";
  for (const auto& [key, expression] : this->KeyWeights)
  {
    os << " " << key << "=" << expression;
  }
  os << "\n";
}
