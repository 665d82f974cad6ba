// The projector on every model of the conformance suite and the external models (issue 28's
// "random tapes" test, on the real ones): the last coordinate eliminated over a range around each
// reference point. Wherever the search ends within the tolerance, the value is never below the
// maximum of F sampled over the range minus the tolerance; always it is F itself at the point it
// names (bit for bit), never above the enclosure of F over the range, and inside the projector's
// own enclosure of a small box around the point.
#include "conformance_case.h"

#include "Compiler/model.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Language/parser.h"
#include "Project/projector.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>

namespace
{

namespace fc = frep::conformance;

struct Subject
{
  std::string id;
  std::shared_ptr<const frep::Tape> tape;
  std::vector<double> point; // one reference point of x_dim >= 2 coordinates
};

std::vector<Subject> subjects()
{
  const std::filesystem::path shared = FREPKIT_SHARED_DIR;
  std::vector<fc::ConformanceCase> cases =
    fc::load_conformance_suite(shared / "hyperfun" / "conformance");
  std::vector<fc::ConformanceCase> models = fc::load_model_cases(shared / "hyperfun" / "models");
  cases.insert(cases.end(), models.begin(), models.end());
  std::vector<Subject> result;
  for (const fc::ConformanceCase& c : cases)
  {
    if (c.parse.outcome != fc::ParseOutcome::Ok || c.points.empty() || c.mode != fc::Mode::Fresh)
      continue;
    const frep::ParseResult parsed = frep::parse_program(c.source, c.program_path.string());
    if (!parsed.ok() || parsed.program->objects.empty())
      continue;
    const int object =
      frep::ast::select_object(*parsed.program, c.object, frep::ast::NameMatch::Exact);
    const frep::Model::CompileResult compiled = frep::Model::compile(parsed.program, object);
    if (!compiled.model || compiled.model->x_dim() < 2)
      continue;
    // A few reference points per case, spread over its list.
    const std::size_t step = std::max<std::size_t>(1, c.points.size() / 3);
    for (std::size_t i = 0; i < c.points.size(); i += step)
    {
      const fc::CasePoint& p = c.points[i];
      if (static_cast<int>(p.x.size()) != compiled.model->x_dim() ||
          !std::all_of(p.x.begin(), p.x.end(), [](double v) { return std::isfinite(v); }))
        continue;
      result.push_back({ c.id(), compiled.model->tape(p.a), p.x });
    }
  }
  return result;
}

TEST(ProjectionModels, ValuesLieBetweenTheSampledMaximumAndTheEnclosure)
{
  const std::vector<Subject> all = subjects();
  ASSERT_GT(all.size(), 100u);
  std::size_t resolved = 0, checked = 0;
  for (const Subject& s : all)
  {
    const std::size_t n = s.tape->input_count;
    const double t = s.point[n - 1];
    const frep::Interval range{ t - 0.5, t + 0.5 };
    frep::project::ProjectorOptions options;
    options.tolerance = 1e-3;
    options.max_boxes = 512;
    options.band = INFINITY; // the value within the tolerance everywhere
    frep::project::Projector projector(s.tape, { range }, options);
    const std::vector<double> kept(s.point.begin(), s.point.end() - 1);
    const frep::project::Maximum m = projector.maximise(kept);
    ++checked;

    frep::PointEvaluator point(s.tape);
    std::vector<double> x = kept;
    x.push_back(0.0);
    double sampled = -INFINITY;
    for (int i = 0; i <= 64; ++i)
    {
      x.back() = range.lo + (range.hi - range.lo) * (i / 64.0);
      const double v = point.value(x);
      if (!std::isnan(v))
        sampled = std::max(sampled, v);
    }
    if (std::isnan(m.value))
    {
      EXPECT_EQ(sampled, -INFINITY) << s.id << ": NaN although F has values over the range";
      continue;
    }
    x.back() = m.at[0];
    EXPECT_EQ(std::bit_cast<std::uint64_t>(point.value(x)), std::bit_cast<std::uint64_t>(m.value))
      << s.id << ": the value is not F at the point it names";
    if (m.resolved)
    {
      ++resolved;
      EXPECT_GE(m.value, sampled - options.tolerance) << s.id;
    }
    frep::IntervalEvaluator intervals(s.tape);
    std::vector<frep::Interval> box;
    for (const double k : kept)
      box.push_back(frep::Interval::point(k));
    box.push_back(range);
    const frep::IntervalResult whole = intervals.evaluate(box);
    EXPECT_LE(m.value, whole.value.hi) << s.id;

    std::vector<frep::Interval> around;
    for (const double k : kept)
      around.push_back({ k - 1e-3, k + 1e-3 });
    const frep::IntervalResult enclosure = projector.enclose(around);
    // With the default band the values differ beyond it, and the enclosure still holds them.
    frep::project::Projector banded(s.tape, { range }, frep::project::ProjectorOptions{});
    const double v = banded.maximise(kept).value;
    const frep::IntervalResult banded_enclosure = banded.enclose(around);
    if (!std::isnan(v))
    {
      EXPECT_GE(v, banded_enclosure.value.lo) << s.id;
      EXPECT_LE(v, banded_enclosure.value.hi) << s.id;
      EXPECT_EQ(v >= 0, m.value >= 0 || std::abs(m.value) <= options.tolerance) << s.id;
    }
    EXPECT_GE(m.value, enclosure.value.lo) << s.id;
    EXPECT_LE(m.value, enclosure.value.hi) << s.id;
  }
  // Most searches end by the tolerance (those that do not have opaque calls or NaNs).
  EXPECT_GT(resolved, checked * 3 / 4) << resolved << " of " << checked;
  std::cout << "[ projection ] " << resolved << " of " << checked
            << " reference points resolved within the tolerance\n";
}

} // namespace
