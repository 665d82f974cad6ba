// vtkFRepSpaceTimeQuery: against analytic answers. VOLUME: a sphere growing as r = 0.5 + 0.5 t
// has volume 4/3 pi r^3 at each time (2 % at 48 samples), one piece, genus 0. PRESENCE: the
// point (0.6, 0, 0) is inside a sphere of radius 0.5 + 0.3 sin(2 pi t) while sin > 1/3, two
// intervals of [0, 2]. CONTACT: spheres of radii 0.5 and 0.7 approaching at speeds 1 and 2 first
// touch at t = 2.8 / 3, at x1 = -2 + 0.933333 + 0.5. TOPOLOGY: two balls of radius 0.45 at
// x1 = +-(0.3 + 0.4 t) part at t = 0.375 (one row: 1 piece -> 2, within TimeTolerance). Each bad
// request is one error and an empty table; defaults, PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepSpaceTimeQuery.h"
#include "vtkFRepSlice.h"
#include "vtkHyperFunSource.h"
#include "vtkNew.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <cmath>
#include <sstream>

namespace
{
const char* Growing = "g(x[4], a[1]) { g = (0.5 + 0.5*x[4])^2 - (x[1]^2 + x[2]^2 + x[3]^2); }";
const char* Pulsing =
  "p(x[4], a[1]) { p = (0.5 + 0.3*sin(6.283185307179586*x[4]))^2 - (x[1]^2 + x[2]^2 + x[3]^2); }";
// Radius 0.5 from x1 = -2 at speed 1; radius 0.7 from x1 = 2 at speed -2.
const char* Left = "l(x[4], a[1]) { l = 0.25 - ((x[1] + 2 - x[4])^2 + x[2]^2 + x[3]^2); }";
const char* Right = "r(x[4], a[1]) { r = 0.49 - ((x[1] - 2 + 2*x[4])^2 + x[2]^2 + x[3]^2); }";
const char* Parting = "p(x[4], a[1]) { c = 0.3 + 0.4*x[4];"
                      " p = max(0.2025 - ((x[1] - c)^2 + x[2]^2 + x[3]^2),"
                      " 0.2025 - ((x[1] + c)^2 + x[2]^2 + x[3]^2)); }";

double At(vtkTable* table, const char* column, int row)
{
  return table->GetColumnByName(column) ? table->GetValueByName(row, column).ToDouble() : NAN;
}
}

int TestFRepSpaceTimeQuery(int, char*[])
{
  int failures = 0;
  constexpr double pi = 3.14159265358979323846;
  vtkNew<vtkHyperFunSource> growing;
  growing->SetModelText(Growing);
  growing->SetCoordinateRange(0, -1.2, 1.2);
  growing->SetCoordinateRange(1, -1.2, 1.2);
  growing->SetCoordinateRange(2, -1.2, 1.2);
  vtkNew<vtkFRepSpaceTimeQuery> query;
  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(query);

  // --- defaults
  FREPKIT_CHECK(failures, query->GetQuery() == vtkFRepSpaceTimeQuery::VOLUME);
  FREPKIT_CHECK(failures, query->GetTimeCoordinate() == 3);
  FREPKIT_CHECK(failures, query->GetTimeRange()[0] == 0.0 && query->GetTimeRange()[1] == 1.0);
  FREPKIT_CHECK(failures, query->GetTimeTolerance() == 1e-4);
  FREPKIT_CHECK(failures, query->GetSteps() == 11 && query->GetSamples() == 48);

  // --- VOLUME
  query->SetInputConnection(growing->GetOutputPort());
  query->SetSteps(3);
  query->Update();
  vtkTable* table = query->GetOutput();
  FREPKIT_CHECK(failures, events->Errors == 0 && table->GetNumberOfRows() == 3);
  for (int i = 0; i < 3; ++i)
  {
    const double t = 0.5 * i, r = 0.5 + 0.5 * t, expected = 4.0 / 3.0 * pi * r * r * r;
    FREPKIT_CHECK(failures, At(table, "time", i) == t);
    FREPKIT_CHECK(failures, std::abs(At(table, "volume", i) - expected) < 0.02 * expected);
    FREPKIT_CHECK(failures, At(table, "pieces", i) == 1.0 && At(table, "genus", i) == 0.0);
  }

  // --- PRESENCE: inside while 0.5 + 0.3 sin(2 pi t) > 0.6, i.e. sin > 1/3
  vtkNew<vtkHyperFunSource> pulsing;
  pulsing->SetModelText(Pulsing);
  query->SetInputConnection(pulsing->GetOutputPort());
  query->SetQueryToPresence();
  query->SetTimeRange(0, 2);
  query->SetPoint(0.6, 0, 0);
  query->SetTimeTolerance(1e-6);
  query->Update();
  table = query->GetOutput();
  const double a = std::asin(1.0 / 3.0) / (2 * pi), b = 0.5 - a;
  FREPKIT_CHECK(failures, events->Errors == 0 && table->GetNumberOfRows() == 2);
  for (int k = 0; k < 2 && table->GetNumberOfRows() == 2; ++k)
  {
    FREPKIT_CHECK(failures, std::abs(At(table, "enter", k) - (a + k)) < 2e-6);
    FREPKIT_CHECK(failures, std::abs(At(table, "leave", k) - (b + k)) < 2e-6);
  }

  // --- CONTACT
  vtkNew<vtkHyperFunSource> left, right;
  left->SetModelText(Left);
  right->SetModelText(Right);
  left->SetCoordinateRange(0, -3, 3);
  left->SetCoordinateRange(1, -1, 1);
  left->SetCoordinateRange(2, -1, 1);
  query->SetInputConnection(left->GetOutputPort());
  query->SetQueryToContact();
  query->SetTimeRange(0, 2);
  query->SetTimeTolerance(1e-4);
  query->Update();
  FREPKIT_CHECK(failures, events->Errors == 1 && query->GetOutput()->GetNumberOfColumns() == 0);
  FREPKIT_CHECK(failures, events->ErrorText.find("second object") != std::string::npos);
  events->Clear();
  query->SetSecondObjectConnection(right->GetOutputPort());
  query->Update();
  table = query->GetOutput();
  FREPKIT_CHECK(failures, events->Errors == 0 && table->GetNumberOfRows() == 1);
  FREPKIT_CHECK(failures, At(table, "found", 0) == 1.0);
  FREPKIT_CHECK(failures, std::abs(At(table, "time", 0) - 2.8 / 3.0) < 2e-4);
  FREPKIT_CHECK(failures, At(table, "time_lo", 0) <= 2.8 / 3.0 + 1e-9);
  FREPKIT_CHECK(failures, std::abs(At(table, "x1", 0) - (-2 + 2.8 / 3.0 + 0.5)) < 1e-2);
  // Never: the second solid leaves the box before they meet.
  query->SetTimeRange(0, 0.5);
  query->Update();
  FREPKIT_CHECK(failures, At(query->GetOutput(), "found", 0) == 0.0);
  FREPKIT_CHECK(failures, std::isnan(At(query->GetOutput(), "time", 0)));

  // --- TOPOLOGY: the grid (49 samples over [-2, 2] and [-1, 1]) has a point at the origin,
  // where the balls meet until c = 0.45.
  vtkNew<vtkHyperFunSource> parting;
  parting->SetModelText(Parting);
  parting->SetCoordinateRange(0, -2, 2);
  parting->SetCoordinateRange(1, -1, 1);
  parting->SetCoordinateRange(2, -1, 1);
  query->SetInputConnection(parting->GetOutputPort());
  query->SetQueryToTopology();
  query->SetTimeRange(0, 1);
  query->SetSteps(5);
  query->SetSamples(49);
  query->SetTimeTolerance(1e-3);
  events->Clear();
  query->Update();
  table = query->GetOutput();
  FREPKIT_CHECK(failures, events->Errors == 0 && table->GetNumberOfRows() == 1);
  FREPKIT_CHECK(failures, At(table, "before", 0) <= 0.375 && At(table, "after", 0) >= 0.375);
  FREPKIT_CHECK(failures, At(table, "after", 0) - At(table, "before", 0) <= 1e-3);
  FREPKIT_CHECK(failures, At(table, "pieces_before", 0) == 1.0 && At(table, "pieces_after", 0) == 2.0);
  FREPKIT_CHECK(failures, At(table, "genus_before", 0) == 0.0 && At(table, "genus_after", 0) == 0.0);
  query->SetTimeRange(0, 0.3); // one piece throughout: no row
  query->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && query->GetOutput()->GetNumberOfRows() == 0);
  query->SetSteps(11);
  query->SetSamples(48);
  query->SetTimeTolerance(1e-4);
  query->SetInputConnection(left->GetOutputPort());
  query->SetQueryToContact();

  // --- bad requests: one error each, an empty table
  auto refused = [&](const char* expected)
  {
    events->Clear();
    query->Update();
    const bool ok = events->Errors == 1 && query->GetOutput()->GetNumberOfColumns() == 0 &&
      events->ErrorText.find(expected) != std::string::npos;
    if (!ok)
      std::cerr << "expected one error with '" << expected << "', got " << events->Errors << ": "
                << events->ErrorText << "\n";
    return ok;
  };
  query->SetTimeCoordinate(7);
  FREPKIT_CHECK(failures, refused("TimeCoordinate 7"));
  query->SetTimeCoordinate(3);
  query->SetTimeTolerance(0);
  FREPKIT_CHECK(failures, refused("TimeTolerance"));
  query->SetTimeTolerance(1e-4);
  query->SetTimeRange(1, 0);
  FREPKIT_CHECK(failures, refused("time range"));
  query->SetTimeRange(0, 1);
  vtkNew<vtkFRepSlice> slice; // time fixed upstream
  slice->SetInputConnection(left->GetOutputPort());
  slice->SetFixedValue(3, 0.5);
  query->SetInputConnection(slice->GetOutputPort());
  FREPKIT_CHECK(failures, refused("time coordinate is fixed"));
  slice->SetFixedValue(3, NAN); // released
  slice->SetFixedValue(2, 0.0);
  query->SetQueryToVolume();
  FREPKIT_CHECK(failures, refused("x3 is fixed"));
  query->SetInputConnection(growing->GetOutputPort());
  query->SetSamples(1);
  FREPKIT_CHECK(failures, refused("Samples"));

  std::ostringstream printed;
  query->Print(printed);
  FREPKIT_CHECK(failures, printed.str().find("Query: VOLUME") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("Samples: 1") != std::string::npos);
  query->SetInputConnection(parting->GetOutputPort());
  query->SetQueryToTopology();
  query->SetSamples(33);
  query->SetSteps(1);
  FREPKIT_CHECK(failures, refused("at least two times"));
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
