#include "vtkFRepSpaceTimeQuery.h"

#include "vtkFRepObject.h"

#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkTable.h"

#include "Project/space_time.h"

#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkFRepSpaceTimeQuery);

namespace
{

// An empty column (a table takes a column only when its rows match the others': add them all
// before filling any).
vtkDoubleArray* AddColumn(vtkTable* table, const std::string& name)
{
  vtkNew<vtkDoubleArray> column;
  column->SetName(name.c_str());
  table->AddColumn(column);
  return column;
}

// A column of one row.
void AddValue(vtkTable* table, const std::string& name, double value)
{
  vtkNew<vtkDoubleArray> column;
  column->SetName(name.c_str());
  column->InsertNextValue(value);
  table->AddColumn(column);
}

// The object's intervals of every model coordinate but time, a fixed one as [v, v].
std::vector<frep::Interval> SpaceBox(vtkFRepObject* object, int time)
{
  std::vector<frep::Interval> box;
  for (int c = 0; c < object->GetModelDimension(); ++c)
  {
    if (c == time)
    {
      continue;
    }
    double range[2];
    object->GetCoordinateRange(c, range);
    if (object->IsCoordinateFixed(c))
    {
      range[0] = range[1] = object->GetFixedValue(c);
    }
    box.push_back({ range[0], range[1] });
  }
  return box;
}

frep::project::SpaceTimeOptions Options(vtkFRepObject* object, double timeTolerance)
{
  frep::project::SpaceTimeOptions options;
  options.time_tolerance = timeTolerance;
  options.parameters = object->GetParameters();
  return options;
}

} // namespace

//------------------------------------------------------------------------------
vtkFRepSpaceTimeQuery::vtkFRepSpaceTimeQuery()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkFRepSpaceTimeQuery::~vtkFRepSpaceTimeQuery() = default;

//------------------------------------------------------------------------------
int vtkFRepSpaceTimeQuery::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkFRepObject");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkFRepSpaceTimeQuery::SpaceIsFree(vtkFRepObject* object, const char* query)
{
  for (int c = 0; c < object->GetModelDimension(); ++c)
  {
    if (c != this->TimeCoordinate && object->IsCoordinateFixed(c))
    {
      return object->GetCoordinateName(c) + " is fixed by the input: " + query +
        " needs every coordinate of space free";
    }
  }
  return {};
}

//------------------------------------------------------------------------------
std::string vtkFRepSpaceTimeQuery::Volume(vtkFRepObject* object, vtkTable* table)
{
  if (std::string fixed = this->SpaceIsFree(object, "VOLUME"); !fixed.empty())
  {
    return fixed;
  }
  if (this->Steps < 1 || this->Samples < 2)
  {
    return "Steps must be >= 1 and Samples >= 2";
  }
  const std::vector<frep::Interval> space = SpaceBox(object, this->TimeCoordinate);
  const frep::project::SpaceTimeOptions options = Options(object, this->TimeTolerance);
  vtkDoubleArray* time = AddColumn(table, "time");
  vtkDoubleArray* measure = AddColumn(table, space.size() == 2 ? "area" : "volume");
  vtkDoubleArray* pieces = AddColumn(table, "pieces");
  vtkDoubleArray* genus = AddColumn(table, "genus");
  const double lo = this->TimeRange[0], hi = this->TimeRange[1];
  for (int i = 0; i < this->Steps; ++i)
  {
    // One time at a time: progress after each, and an abort between them.
    const double t = this->Steps == 1 ? lo : lo + (hi - lo) * (i / double(this->Steps - 1));
    const frep::project::SectionMeasures one = frep::project::section_measures(
      *object->GetModel(), { this->TimeCoordinate + 1, t, t }, space, 1, this->Samples, options);
    if (!one.ok())
    {
      return one.error;
    }
    const frep::project::SectionMeasure& m = one.table.front();
    time->InsertNextValue(t);
    measure->InsertNextValue(m.measure);
    pieces->InsertNextValue(static_cast<double>(m.components));
    genus->InsertNextValue(static_cast<double>(m.genus));
    this->UpdateProgress((i + 1.0) / this->Steps);
    if (this->CheckAbort())
    {
      table->Initialize();
      return {};
    }
  }
  return {};
}

//------------------------------------------------------------------------------
std::string vtkFRepSpaceTimeQuery::Presence(vtkFRepObject* object, vtkTable* table)
{
  std::vector<double> at;
  int k = 0;
  for (int c = 0; c < object->GetModelDimension(); ++c)
  {
    double range[2];
    object->GetCoordinateRange(c, range);
    if (c == this->TimeCoordinate)
      at.push_back(0.0); // unread
    else if (object->IsCoordinateFixed(c))
      at.push_back(object->GetFixedValue(c));
    else
      at.push_back(k < 3 ? this->Point[k] : 0.5 * (range[0] + range[1]));
    k += c != this->TimeCoordinate ? 1 : 0;
  }
  const frep::project::Presence p = frep::project::presence(*object->GetModel(),
    { this->TimeCoordinate + 1, this->TimeRange[0], this->TimeRange[1] }, at,
    Options(object, this->TimeTolerance));
  if (!p.ok())
  {
    return p.error;
  }
  vtkDoubleArray* enter = AddColumn(table, "enter");
  vtkDoubleArray* leave = AddColumn(table, "leave");
  for (const frep::Interval& inside : p.inside)
  {
    enter->InsertNextValue(inside.lo);
    leave->InsertNextValue(inside.hi);
  }
  return {};
}

//------------------------------------------------------------------------------
std::string vtkFRepSpaceTimeQuery::Contact(vtkFRepObject* a, vtkFRepObject* b, vtkTable* table)
{
  if (!b || !b->HasModel())
  {
    return "CONTACT needs a second object on port 1";
  }
  const frep::project::Contact contact = frep::project::first_contact(a->GetModel(),
    b->GetModel(), { this->TimeCoordinate + 1, this->TimeRange[0], this->TimeRange[1] },
    SpaceBox(a, this->TimeCoordinate), Options(a, this->TimeTolerance));
  if (!contact.ok())
  {
    return contact.error;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkNew<vtkIntArray> found;
  found->SetName("found");
  found->InsertNextValue(contact.found ? 1 : 0);
  table->AddColumn(found);
  AddValue(table, "time", contact.found ? contact.time : nan);
  AddValue(table, "time_lo", contact.time_lo);
  for (int c = 0; c < a->GetModelDimension(); ++c)
  {
    const bool known = contact.found && c < static_cast<int>(contact.where.size());
    AddValue(table, a->GetCoordinateName(c), known ? contact.where[c] : nan);
  }
  return {};
}

//------------------------------------------------------------------------------
std::string vtkFRepSpaceTimeQuery::Topology(vtkFRepObject* object, vtkTable* table)
{
  if (std::string fixed = this->SpaceIsFree(object, "TOPOLOGY"); !fixed.empty())
  {
    return fixed;
  }
  frep::project::SpaceTimeOptions options = Options(object, this->TimeTolerance);
  options.progress = [this](double done)
  {
    this->UpdateProgress(done);
    return !this->CheckAbort();
  };
  const frep::project::TopologyTrack track = frep::project::topology_events(*object->GetModel(),
    { this->TimeCoordinate + 1, this->TimeRange[0], this->TimeRange[1] },
    SpaceBox(object, this->TimeCoordinate), this->Steps, this->Samples, this->TimeTolerance,
    options);
  if (track.cancelled)
  {
    table->Initialize();
    return {};
  }
  if (!track.ok())
  {
    return track.error;
  }
  vtkDoubleArray* columns[6];
  const char* names[6] = { "before", "after", "pieces_before", "pieces_after", "genus_before",
    "genus_after" };
  for (int k = 0; k < 6; ++k)
  {
    columns[k] = AddColumn(table, names[k]);
  }
  for (const frep::project::TopologyEvent& e : track.events)
  {
    const double row[6] = { e.before, e.after, double(e.components_before),
      double(e.components_after), double(e.genus_before), double(e.genus_after) };
    for (int k = 0; k < 6; ++k)
    {
      columns[k]->InsertNextValue(row[k]);
    }
  }
  return {};
}

//------------------------------------------------------------------------------
int vtkFRepSpaceTimeQuery::RequestData(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkTable* output = vtkTable::GetData(outInfo);
  vtkFRepObject* first = vtkFRepObject::GetData(inInfo[0]);
  vtkFRepObject* second =
    inInfo[1]->GetNumberOfInformationObjects() > 0 ? vtkFRepObject::GetData(inInfo[1]) : nullptr;
  output->Initialize();
  std::string problem;
  if (!first || !first->HasModel())
    problem = "no object on port 0";
  else if (this->TimeCoordinate < 0 || this->TimeCoordinate >= first->GetModelDimension())
    problem = "TimeCoordinate " + std::to_string(this->TimeCoordinate) + ": the model has " +
      std::to_string(first->GetModelDimension()) + " coordinates";
  else if (first->IsCoordinateFixed(this->TimeCoordinate))
    problem = "the time coordinate is fixed by the input; ask the object before fixing it";
  else if (!(this->TimeTolerance > 0.0))
    problem = "TimeTolerance must be > 0";
  else if (this->Query == VOLUME)
    problem = this->Volume(first, output);
  else if (this->Query == PRESENCE)
    problem = this->Presence(first, output);
  else if (this->Query == TOPOLOGY)
    problem = this->Topology(first, output);
  else
    problem = this->Contact(first, second, output);
  if (!problem.empty())
  {
    output->Initialize();
    vtkErrorMacro(<< problem << "; the table is empty");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkFRepSpaceTimeQuery::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = { "VOLUME", "PRESENCE", "CONTACT", "TOPOLOGY" };
  os << indent << "Query: " << names[this->Query] << "\n";
  os << indent << "TimeCoordinate: " << this->TimeCoordinate << "\n";
  os << indent << "TimeRange: " << this->TimeRange[0] << " " << this->TimeRange[1] << "\n";
  os << indent << "TimeTolerance: " << this->TimeTolerance << "\n";
  os << indent << "Steps: " << this->Steps << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "Point: " << this->Point[0] << " " << this->Point[1] << " " << this->Point[2]
     << "\n";
}
