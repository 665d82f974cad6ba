// load_model, the one loading call of every tool: files and text, .hf and .vm, the object rule,
// HyperFun library files (their objects called like the file's own, their errors naming them),
// and the same diagnostics for every kind of bad input.
#include "Compiler/load_model.h"
#include "Eval/point_evaluator.h"
#include "Semantics/detail/runtime_messages.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace frep
{
namespace
{

namespace fs = std::filesystem;

/// A fresh folder for one test's files, removed afterwards.
class LoadModel : public ::testing::Test
{
protected:
  void SetUp() override
  {
    dir_ = fs::temp_directory_path() /
           ("frep_load_model_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const
  {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  fs::path dir_;
};

constexpr const char* kBall = "ball(x[3], a[1]) { ball = a[1]^2 - x[1]^2 - x[2]^2 - x[3]^2; }\n";

double value_at(const Model& model, std::vector<double> point, std::vector<double> a = { 1.0 })
{
  PointEvaluator evaluator(model.tape(a));
  return evaluator.value(point);
}

TEST_F(LoadModel, AFileLoadsItsDefaultObjectOrTheNamedOne)
{
  const std::string path = write("two.hf",
    std::string(kBall) + "My_Model(x[3], a[1]) { array r[1]; r[1] = 2; my_model = ball(x, r); }\n");
  const LoadedModel loaded = load_model(ModelSource::file(path));
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  EXPECT_EQ(loaded.model->name(), "my_model");
  EXPECT_EQ(loaded.object, 1);
  EXPECT_EQ(value_at(*loaded.model, { 1, 0, 0 }), 3.0);

  LoadOptions options;
  options.object = "BALL";
  const LoadedModel ball = load_model(ModelSource::file(path), options);
  ASSERT_TRUE(ball.ok()) << ball.message();
  EXPECT_EQ(ball.model->name(), "ball");
  EXPECT_EQ(value_at(*ball.model, { 1, 0, 0 }, { 3.0 }), 8.0);
}

TEST_F(LoadModel, TextAndFileGiveTheSameModel)
{
  const std::string path = write("ball.hf", kBall);
  const LoadedModel from_file = load_model(ModelSource::file(path));
  const LoadedModel from_text = load_model(ModelSource::from_text(kBall));
  ASSERT_TRUE(from_file.ok() && from_text.ok());
  EXPECT_EQ(from_text.file, "<string>");
  for (double x : { -1.5, 0.25, 0.7 })
  {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(value_at(*from_file.model, { x, 0.1, 0.2 })),
      std::bit_cast<std::uint64_t>(value_at(*from_text.model, { x, 0.1, 0.2 })));
  }
}

TEST_F(LoadModel, AVmTapeIsReadByItsExtensionFromAFileOrText)
{
  const std::string tape = "# a unit circle\n_0 var-x\n_1 var-y\n_2 square _0\n_3 square _1\n"
                           "_4 add _2 _3\n_5 const 1\n_6 sub _4 _5\n";
  const LoadedModel file = load_model(ModelSource::file(write("circle.VM", tape)));
  ASSERT_TRUE(file.ok()) << file.message();
  EXPECT_EQ(value_at(*file.model, { 0.5, 0, 0 }), 0.75); // F = -(x^2 + y^2 - 1)
  const LoadedModel text = load_model(ModelSource::from_text(tape, "circle.vm"));
  ASSERT_TRUE(text.ok()) << text.message();
  EXPECT_EQ(value_at(*text.model, { 0.5, 0, 0 }), 0.75);
  // The same text under a .hf name is HyperFun, which it is not.
  EXPECT_FALSE(load_model(ModelSource::from_text(tape, "circle.hf")).ok());
}

TEST_F(LoadModel, BadInputIsADiagnosticNamingTheFile)
{
  const std::string missing = (dir_ / "missing.hf").string();
  const LoadedModel none = load_model(ModelSource::file(missing));
  ASSERT_EQ(none.diagnostics.size(), 1u);
  EXPECT_EQ(none.diagnostics[0].file, missing);
  EXPECT_FALSE(none.diagnostics[0].location.valid());
  EXPECT_NE(none.diagnostics[0].message.find("cannot open the model file"), std::string::npos);
  EXPECT_EQ(none.program, nullptr);

  const LoadedModel empty = load_model(ModelSource::from_text("-- nothing\n", "empty.hf"));
  ASSERT_EQ(empty.diagnostics.size(), 1u);
  EXPECT_EQ(empty.diagnostics[0].format(), "empty.hf: error: the file defines no object");

  LoadOptions cube;
  cube.object = "cube";
  const LoadedModel wrong = load_model(ModelSource::from_text(kBall, "ball.hf"), cube);
  ASSERT_EQ(wrong.diagnostics.size(), 1u);
  EXPECT_EQ(
    wrong.diagnostics[0].format(), "ball.hf: error: no object named 'cube' (objects: ball)");
  EXPECT_NE(wrong.program, nullptr); // parsed: tools may still list the objects

  const LoadedModel syntax = load_model(ModelSource::from_text("ball(x[3]) { ball = ; }", "s.hf"));
  ASSERT_FALSE(syntax.diagnostics.empty());
  EXPECT_EQ(syntax.diagnostics[0].file, "s.hf");
  EXPECT_EQ(syntax.diagnostics[0].location.line, 1);
}

TEST_F(LoadModel, AHyperFunLibraryFileIsCalledLikeTheFilesOwnObjects)
{
  LoadOptions options;
  options.libraries = { write("shapes.hf", kBall) };
  const std::string main_text =
    "blob(x[3], a[1]) { array r[1]; r[1] = 2; blob = ball(x, r) | ball(x, a); }\n";
  const LoadedModel loaded = load_model(ModelSource::from_text(main_text, "main.hf"), options);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  // The default object is the file's own first object, not the library's.
  EXPECT_EQ(loaded.model->name(), "blob");
  EXPECT_EQ(loaded.program->first_own_object, 1);

  // Bit for bit what the same objects pasted into one file give.
  const LoadedModel pasted = load_model(
    ModelSource::from_text(std::string(kBall) + main_text, "pasted.hf"), LoadOptions{ "blob" });
  ASSERT_TRUE(pasted.ok()) << pasted.message();
  for (double x : { -2.5, -0.3, 0.0, 1.1, 3.0 })
  {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(value_at(*loaded.model, { x, 0.5, -0.25 })),
      std::bit_cast<std::uint64_t>(value_at(*pasted.model, { x, 0.5, -0.25 })))
      << x;
  }
}

TEST_F(LoadModel, ErrorsInsideALibraryObjectNameTheLibraryFile)
{
  LoadOptions options;
  const std::string library = write("lib.hf", "\n\ninv(x[3], a[1]) { inv = 1 / x[1]; }\n");
  options.libraries = { library };
  const LoadedModel loaded =
    load_model(ModelSource::from_text("m(x[3], a[1]) { m = inv(x, a); }\n", "main.hf"), options);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  const auto tape = loaded.model->tape();
  PointEvaluator evaluator(tape);
  std::vector<double> out(1);
  const int error = evaluator.evaluate(std::vector<double>{ 0.0, 1.0, 1.0 }, out);
  ASSERT_GT(error, 0);
  const TapeError& e = tape->errors[static_cast<std::size_t>(error - 1)];
  EXPECT_EQ(e.message, messages::kDivisionByZero);
  EXPECT_EQ(e.file, library);
  EXPECT_EQ(e.location.line, 3);
}

// An interpreted model (a data-dependent loop) raising the same message at the same line and
// column as its library file: two errors, each naming its own file.
TEST_F(LoadModel, AnInterpretedModelsErrorsNameTheirFile)
{
  LoadOptions options;
  const std::string library = write("lib.hf", "inv(x[3], a[1]) {\n  inv = 1 / x[1];\n}\n");
  options.libraries = { library };
  const LoadedModel loaded =
    load_model(ModelSource::from_text("m(x[3], a[1]) {\n"
                                      "  mmm = 1 / x[2];\n"
                                      "  i = 0;\n"
                                      "  while i < x[3] loop i = i + 1; endloop;\n"
                                      "  m = inv(x, a) + mmm + i;\n"
                                      "}\n",
                 "main.hf"),
      options);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  ASSERT_FALSE(loaded.model->is_compiled()); // the loop: the interpreter runs the object
  const auto tape = loaded.model->tape();
  PointEvaluator evaluator(tape);
  std::vector<double> out(1);
  const auto error_at = [&](std::vector<double> p) -> const TapeError*
  {
    const int id = evaluator.evaluate(p, out);
    return id > 0 ? &tape->errors[static_cast<std::size_t>(id - 1)] : nullptr;
  };
  const TapeError* in_model = error_at({ 1.0, 0.0, 1.0 });   // x[2] = 0: the model's division
  const TapeError* in_library = error_at({ 0.0, 1.0, 1.0 }); // x[1] = 0: the library's
  ASSERT_TRUE(in_model && in_library);
  EXPECT_EQ(in_model->message, messages::kDivisionByZero);
  EXPECT_EQ(in_library->message, messages::kDivisionByZero);
  EXPECT_EQ(in_model->location.line, in_library->location.line);
  EXPECT_EQ(in_model->location.column, in_library->location.column);
  EXPECT_EQ(in_model->file, "main.hf");
  EXPECT_EQ(in_library->file, library);
}

TEST_F(LoadModel, LibraryProblemsAreDiagnosticsNamingTheLibrary)
{
  LoadOptions missing;
  missing.libraries = { (dir_ / "nowhere.hf").string() };
  const LoadedModel a = load_model(ModelSource::from_text(kBall, "main.hf"), missing);
  ASSERT_EQ(a.diagnostics.size(), 1u);
  EXPECT_EQ(a.diagnostics[0].file, missing.libraries[0]);
  EXPECT_NE(a.diagnostics[0].message.find("cannot open the library file"), std::string::npos);

  LoadOptions broken;
  broken.libraries = { write("broken.hf", "\nbad(x[3]) { bad = ; }\n") };
  const LoadedModel b = load_model(ModelSource::from_text(kBall, "main.hf"), broken);
  ASSERT_FALSE(b.diagnostics.empty());
  EXPECT_EQ(b.diagnostics[0].file, broken.libraries[0]);
  EXPECT_EQ(b.diagnostics[0].location.line, 2);

  LoadOptions twice;
  twice.libraries = { write("ball.hf", kBall) };
  const LoadedModel c = load_model(ModelSource::from_text(kBall, "main.hf"), twice);
  ASSERT_EQ(c.diagnostics.size(), 1u);
  EXPECT_EQ(c.diagnostics[0].file, "main.hf");
  EXPECT_NE(
    c.diagnostics[0].message.find("Body name is not unique (library file"), std::string::npos)
    << c.diagnostics[0].message;

  LoadOptions not_a_library;
  not_a_library.libraries = { write("libnothing.so", "not an ELF file") };
  const LoadedModel d = load_model(ModelSource::from_text(kBall, "main.hf"), not_a_library);
  ASSERT_EQ(d.diagnostics.size(), 1u);
  EXPECT_EQ(d.diagnostics[0].file, not_a_library.libraries[0]);
}

TEST(LoadModelText, DescribeAndExtraParameters)
{
  const LoadedModel loaded = load_model(ModelSource::from_text(kBall));
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ(describe_object(loaded.program->objects[0]), "ball(x[3], a[1], s[1])");
  EXPECT_EQ(extra_parameters_warning("ball", 1, 1), "");
  EXPECT_EQ(extra_parameters_warning("ball", 1, 3),
    "3 parameters given, ball has a[1]: the extra ones are ignored");
}

} // namespace
} // namespace frep
