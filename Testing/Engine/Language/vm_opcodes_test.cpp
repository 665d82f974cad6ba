// The .vm reader's opcodes beyond the arithmetic core (recip exp ln sin cos tan asin acos atan
// atan2 floor ceil round compare and or not mod): each one's value rule at chosen points and
// edge cases, through the compiled tape (point and batch evaluators) and the interpreter, which
// must agree bit for bit; the rules are Language/vm_reader.h's. Every model compiles (no
// interpreter fallback, no opaque call).
#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Language/vm_reader.h"
#include "Semantics/interpreter.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace frep
{
namespace
{

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

bool same_bits(double a, double b)
{
  return (std::isnan(a) && std::isnan(b)) ||
         std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// The tape's value at a point (not F: the sign flip undone), or the run-time error.
struct Outcome
{
  double value = 0;
  std::string error; ///< empty: none
  SourceLocation at;
};

/// A .vm model compiled once; at() evaluates a point by the compiled tape and checks the
/// interpreter and the batch evaluator against it.
class VmModel
{
public:
  explicit VmModel(const std::string& text)
  {
    parsed_ = parse_vm(text, "t.vm");
    EXPECT_TRUE(parsed_.ok()) << (parsed_.ok() ? "" : parsed_.diagnostics.at(0).format());
    if (!parsed_.ok())
    {
      return;
    }
    auto compiled = Model::compile(parsed_.program, 0);
    EXPECT_TRUE(compiled.model);
    model_ = compiled.model;
    EXPECT_TRUE(model_->is_compiled()) << model_->fallback_reason();
    tape_ = model_->specialise({});
    for (const Instruction& i : tape_->code)
    {
      EXPECT_NE(i.op, Opcode::Call) << "an opaque call in the tape of\n" << text;
    }
  }

  bool ok() const { return tape_ != nullptr; }
  const Tape& tape() const { return *tape_; }
  std::shared_ptr<const Tape> shared_tape() const { return tape_; }

  Outcome at(std::vector<double> x) const
  {
    Outcome o;
    if (!tape_)
    {
      o.error = "no model";
      return o;
    }
    x.resize(tape_->input_count, 0.0);
    PointEvaluator point(tape_);
    std::vector<double> out(tape_->outputs.size());
    const int error = point.evaluate(x, out);
    if (error)
    {
      o.error = tape_->errors.at(static_cast<std::size_t>(error - 1)).message;
      o.at = tape_->errors.at(static_cast<std::size_t>(error - 1)).location;
      o.value = kNaN;
    }
    else
    {
      o.value = -out[0]; // F = -tape
    }
    // The interpreter runs the same AST.
    Interpreter interpreter(parsed_.program, 0);
    const PointResult r = interpreter.evaluate(x);
    EXPECT_EQ(r.error.has_value(), error != 0);
    if (r.error && error)
    {
      EXPECT_EQ(r.error->message, o.error);
    }
    if (!r.error && !error)
    {
      EXPECT_TRUE(same_bits(-r.value, o.value)) << -r.value << " vs " << o.value;
    }
    // The batch evaluator, compiled to machine code.
    BatchOptions one;
    one.threads = 1;
    BatchEvaluator batch(tape_, one);
    batch.compiled();
    std::vector<const double*> inputs;
    for (const double& v : x)
    {
      inputs.push_back(&v);
    }
    double value = 0;
    std::uint32_t batch_error = 0;
    batch.evaluate(inputs, 1, &value, &batch_error);
    EXPECT_EQ(batch_error, static_cast<std::uint32_t>(error));
    if (!error)
    {
      EXPECT_TRUE(same_bits(-value, o.value)) << -value << " vs " << o.value;
    }
    return o;
  }

private:
  ParseResult parsed_;
  std::shared_ptr<const Model> model_;
  std::shared_ptr<const Tape> tape_;
};

/// "a var-x\nr OP a\n": the opcode applied to x.
VmModel unary(const std::string& op)
{
  return VmModel("a var-x\nr " + op + " a\n");
}

/// "a var-x\nb var-y\nr OP a b\n".
VmModel binary(const std::string& op)
{
  return VmModel("a var-x\nb var-y\nr " + op + " a b\n");
}

/// A NaN operand without an error: inf - inf (exp 1000 overflows; HyperFun has no exp error).
const char* nan_prefix = "big const 1000\ne exp big\nnan sub e e\n";

void expect_value(const VmModel& m, std::vector<double> x, double expected)
{
  const Outcome o = m.at(x);
  EXPECT_TRUE(o.error.empty()) << o.error << " at x = " << x.at(0);
  EXPECT_TRUE(same_bits(o.value, expected))
    << "x = " << x.at(0) << (x.size() > 1 ? ", y = " + std::to_string(x[1]) : "") << ": got "
    << o.value << ", expected " << expected;
}

void expect_error(const VmModel& m, std::vector<double> x, const std::string& message)
{
  const Outcome o = m.at(x);
  EXPECT_EQ(o.error, message) << "x = " << x.at(0);
}

/// Rust's f64::rem_euclid, Fidget's `mod`.
double rem_euclid(double a, double b)
{
  const double r = std::fmod(a, b);
  return r < 0.0 ? r + std::fabs(b) : r;
}

TEST(VmOpcodes, RecipIsOneOverAWithHyperFunsDivisionCheck)
{
  const VmModel m = unary("recip");
  expect_value(m, { 2.0 }, 0.5);
  expect_value(m, { -3.0 }, 1.0 / -3.0);
  expect_value(m, { 1e-6 }, 1.0 / 1e-6);
  expect_error(m, { 0.0 }, "Division by zero");
  expect_error(m, { -0.0 }, "Division by zero");
  expect_error(m, { 5e-7 }, "Division by zero"); // |a| < 1e-6, as div (Fidget: 2e6)
  const Outcome o = m.at({ 0.0 });
  EXPECT_EQ(o.at.line, 2);
  EXPECT_EQ(o.at.column, 3);
}

TEST(VmOpcodes, ExpAndLn)
{
  const VmModel e = unary("exp");
  expect_value(e, { 0.0 }, 1.0);
  expect_value(e, { 1.5 }, std::exp(1.5));
  expect_value(e, { -800.0 }, 0.0);
  expect_value(e, { 1000.0 }, kInf); // overflow is a value, not an error (as HyperFun's exp)
  const VmModel l = unary("ln");
  expect_value(l, { 1.0 }, 0.0);
  expect_value(l, { 2.5 }, std::log(2.5));
  expect_value(l, { 1e-300 }, std::log(1e-300));
  expect_error(l, { 0.0 }, "Negative for log function");  // Fidget: -inf
  expect_error(l, { -1.0 }, "Negative for log function"); // Fidget: NaN
}

TEST(VmOpcodes, Trigonometry)
{
  for (const char* op : { "sin", "cos", "atan" })
  {
    const VmModel m = unary(op);
    for (const double x : { 0.0, -0.0, 0.5, -2.0, 100.0 })
    {
      const double expected = std::string(op) == "sin"   ? std::sin(x)
                              : std::string(op) == "cos" ? std::cos(x)
                                                         : std::atan(x);
      expect_value(m, { x }, expected);
    }
  }
  const VmModel t = unary("tan");
  expect_value(t, { 0.5 }, std::tan(0.5));
  expect_value(t, { -1.25 }, std::tan(-1.25));
  expect_value(t, { 1.5707 }, std::tan(1.5707)); // |cos| = 9.6e-5: a value
  // |cos a| < 1e-6: HyperFun's tan error (Fidget gives a finite, huge value).
  expect_error(t, { std::numbers::pi / 2 }, "Cannot compute tan for this argument");
}

TEST(VmOpcodes, AsinAndAcosOutsideMinusOneOneAreErrors)
{
  const VmModel s = unary("asin");
  const VmModel c = unary("acos");
  for (const double x : { -1.0, -0.25, 0.0, 0.75, 1.0 })
  {
    expect_value(s, { x }, std::asin(x));
    expect_value(c, { x }, std::acos(x));
  }
  expect_error(s, { 1.0000001 }, "Argument must be in range -1.0 .. +1.0");
  expect_error(c, { -2.0 }, "Argument must be in range -1.0 .. +1.0");
}

TEST(VmOpcodes, Atan2IsAtan2OfTheFirstOperandOverTheSecond)
{
  const VmModel m = binary("atan2");
  expect_value(m, { 1.0, 0.0 }, std::numbers::pi / 2);
  expect_value(m, { 0.0, -1.0 }, std::numbers::pi);
  expect_value(m, { -0.0, -1.0 }, -std::numbers::pi);
  expect_value(m, { 2.0, 3.0 }, std::atan2(2.0, 3.0));
  expect_value(m, { -2.0, -3.0 }, std::atan2(-2.0, -3.0));
  expect_value(m, { 0.0, 0.0 }, 0.0);
}

TEST(VmOpcodes, FloorAndCeil)
{
  const VmModel f = unary("floor");
  const VmModel c = unary("ceil");
  for (const double x : { 0.0, -0.0, 0.5, -0.5, 2.0, -2.0, 2.7, -2.7, 1e300, 4503599627370495.5 })
  {
    expect_value(f, { x }, std::floor(x));
    expect_value(c, { x }, std::ceil(x));
  }
}

TEST(VmOpcodes, RoundIsHalfAwayFromZero)
{
  const VmModel m = unary("round");
  const double cases[] = { 0.0,
    -0.0,
    0.3,
    -0.3,
    0.5,
    -0.5,
    1.5,
    -1.5,
    2.5,
    -2.5,
    2.4999999999999996,
    0.49999999999999994,
    -0.49999999999999994,
    4503599627370495.5,
    -4503599627370495.5,
    4503599627370497.0,
    9007199254740993.0,
    1e300,
    -7.0,
    1e-310 };
  for (const double x : cases)
  {
    expect_value(m, { x }, std::round(x)); // C round = Rust's f32/f64::round
  }
  EXPECT_TRUE(std::signbit(m.at({ -0.3 }).value)); // round(-0.3) = -0
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  for (int k = 0; k < 200; ++k)
  {
    const double x = std::ldexp(std::floor(u(rng) * 64.0), -6) + (k % 2 ? 0.0 : u(rng) * 1e-3);
    expect_value(m, { x }, std::round(x));
  }
  // NaN stays NaN, without an error.
  expect_value(VmModel(std::string(nan_prefix) + "r round nan\n"), { 0.0 }, kNaN);
}

TEST(VmOpcodes, CompareIsMinusOneZeroOrOneAndNaNForNaN)
{
  const VmModel m = binary("compare");
  expect_value(m, { 1.0, 2.0 }, -1.0);
  expect_value(m, { 2.0, 1.0 }, 1.0);
  expect_value(m, { 1.5, 1.5 }, 0.0);
  expect_value(m, { -0.0, 0.0 }, 0.0);
  expect_value(m, { 1.0, 1.0 + 1e-9 }, -1.0); // exact, not HyperFun's 1e-6 tolerance
  expect_value(VmModel(std::string(nan_prefix) + "x var-x\nr compare nan x\n"), { 1.0 }, kNaN);
  expect_value(VmModel(std::string(nan_prefix) + "x var-x\nr compare x nan\n"), { 1.0 }, kNaN);
  expect_value(VmModel("c const 1000\ne exp c\nr compare e e\n"), { 0.0 }, 0.0); // inf == inf
}

TEST(VmOpcodes, AndOrNotTestExactZero)
{
  const VmModel a = binary("and");
  expect_value(a, { 0.0, 5.0 }, 0.0);
  expect_value(a, { -0.0, 5.0 }, -0.0); // returns the zero itself
  expect_value(a, { 2.0, 5.0 }, 5.0);
  expect_value(a, { 1e-9, 5.0 }, 5.0); // nonzero (HyperFun's truthiness would say false)
  expect_value(a, { -3.0, -0.0 }, -0.0);
  const VmModel o = binary("or");
  expect_value(o, { 0.0, 5.0 }, 5.0);
  expect_value(o, { -0.0, 5.0 }, 5.0);
  expect_value(o, { 2.0, 5.0 }, 2.0);
  expect_value(o, { 1e-9, 5.0 }, 1e-9);
  const VmModel n = unary("not");
  expect_value(n, { 0.0 }, 1.0);
  expect_value(n, { -0.0 }, 1.0);
  expect_value(n, { 1e-9 }, 0.0);
  expect_value(n, { -4.0 }, 0.0);
  // NaN is not zero (Fidget: NaN == 0 is false).
  const std::string p(nan_prefix);
  expect_value(VmModel(p + "x var-x\nr and nan x\n"), { 5.0 }, 5.0);
  expect_value(VmModel(p + "x var-x\nr or nan x\n"), { 5.0 }, kNaN);
  expect_value(VmModel(p + "r not nan\n"), { 0.0 }, 0.0);
}

TEST(VmOpcodes, ModIsRemEuclidAtChosenPoints)
{
  const VmModel m = binary("mod");
  const double cases[][2] = { { 7, 3 },
    { -7, 3 },
    { 7, -3 },
    { -7, -3 },
    { 7.5, 2 },
    { -7.5, 2 },
    { 6, 3 },
    { -6, 3 },
    { -2, 1 },
    { 0, 3 },
    { -0.0, 3 },
    { 2, 3 },
    { -2, 3 },
    { 0.3, 0.1 },
    { 1, 0.1 },
    { -1, 0.1 },
    { 0.7, 0.1 },
    { 5.551115123125783e-17, 1 },
    { -1e-20, 1 },
    { 1e15, 0.1 },
    { -1e15, 3.7 },
    { 123456.789, 1e-6 },
    { 1, 1 },
    { 0.9999999999999999, 1 },
    { 3, 0.9999999999999999 },
    { 1e300, 1e299 },
    { 1.4999999999999998, 1.5 },
    { -1.4999999999999998, 1.5 },
    // q = v / m rounds up to the next integer: 78.6 / 0.3 = 262 but fmod = 0.2999999999999972
    { 78.6, 0.3 },
    { -78.6, 0.3 },
    { 78.6, -0.3 },
    { 96.2, 0.1 },
    { -96.2, -0.1 } };
  for (const auto& c : cases)
  {
    expect_value(m, { c[0], c[1] }, rem_euclid(c[0], c[1]));
  }
  EXPECT_TRUE(std::signbit(m.at({ -2.0, 1.0 }).value)); // fmod(-2, 1) = -0, not < 0: stays -0
  EXPECT_EQ(m.at({ -1e-20, 1.0 }).value, 1.0);          // r + |b| rounds to |b|, as in Rust
  // A divisor below 1e-6 is a division by zero (HyperFun's rule, as div; Fidget: NaN for 0).
  expect_error(m, { 5.0, 0.0 }, "Division by zero");
  expect_error(m, { 5.0, -5e-7 }, "Division by zero");
  const Outcome o = m.at({ 5.0, 0.0 });
  EXPECT_EQ(o.at.line, 3);
  EXPECT_EQ(o.at.column, 3);
  // Infinities: fmod(inf, b) is NaN; fmod(a, inf) = a, and -5 + inf = inf.
  const std::string inf = "big const 1000\ninf exp big\nx var-x\n";
  expect_value(VmModel(inf + "r mod inf x\n"), { 1.0 }, kNaN);
  expect_value(VmModel(inf + "r mod x inf\n"), { 5.0 }, 5.0);
  expect_value(VmModel(inf + "r mod x inf\n"), { -5.0 }, kInf);
  expect_value(VmModel(std::string(nan_prefix) + "x var-x\nr mod x nan\n"), { 5.0 }, kNaN);
}

TEST(VmOpcodes, ModIsExactlyFmodBasedOnRandomOperands)
{
  // The exact-residual construction against C fmod, over magnitudes from 1e-6 to 1e12 and
  // quotients up to 2^52 (beyond, the reader documents that n may be off by more than one).
  const VmModel m = binary("mod");
  ASSERT_TRUE(m.ok());
  PointEvaluator point(m.shared_tape());
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-19, 40);
  std::uniform_int_distribution<int> sign(0, 1);
  int checked = 0;
  int rounded_up = 0; // q = |a| / |b| rounded up to an integer above trunc of the exact quotient
  std::vector<double> out(m.tape().outputs.size());
  for (int k = 0; k < 20000; ++k)
  {
    const double a = (sign(rng) ? -1 : 1) * std::ldexp(mantissa(rng), exponent(rng));
    const double b = (sign(rng) ? -1 : 1) * std::ldexp(mantissa(rng), exponent(rng));
    if (std::fabs(b) < 1e-6 || std::fabs(a / b) >= 0x1p52)
    {
      continue;
    }
    // Near-multiples too: a = n * b rounded, where the quotient rounds across an integer.
    const double near = (sign(rng) ? a : std::round(a / b) * b);
    const double x[2] = { near, b };
    ASSERT_EQ(point.evaluate(x, out), 0);
    ASSERT_TRUE(same_bits(-out[0], rem_euclid(near, b)))
      << near << " mod " << b << ": " << -out[0] << " vs " << rem_euclid(near, b);
    ++checked;
    const double v = std::fabs(near), m = std::fabs(b);
    rounded_up += std::trunc(v / m) > std::round((v - std::fmod(v, m)) / m) ? 1 : 0;
  }
  EXPECT_GT(checked, 10000);
  EXPECT_GT(rounded_up, 100);
}

TEST(VmOpcodes, EveryOpcodeInOneTapeCompilesAndAgreesEverywhere)
{
  const char* text = "x var-x\ny var-y\nz var-z\nh const 0.5\nt const 3\n"
                     "r1 recip t\ne exp h\nl ln t\ns sin x\nc cos y\nta tan h\nas asin h\n"
                     "ac acos h\nat atan z\na2 atan2 y x\nf floor x\nce ceil y\nro round z\n"
                     "cm compare x y\nan and cm s\no or f c\nn not ce\nmo mod x t\n"
                     "u1 add r1 e\nu2 add u1 l\nu3 add u2 s\nu4 add u3 ta\nu5 add u4 as\n"
                     "u6 add u5 ac\nu7 add u6 at\nu8 add u7 a2\nu9 add u8 ro\nu10 add u9 an\n"
                     "u11 add u10 o\nu12 add u11 n\nu13 add u12 mo\nu14 add u13 f\n";
  const VmModel m(text);
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m.tape().input_count, 3u);
  for (const double x : { -2.5, -1.0, 0.0, 0.5, 2.0 })
  {
    for (const double y : { -1.5, 0.0, 0.75 })
    {
      for (const double z : { -0.5, 0.5, 2.5 })
      {
        const Outcome o = m.at({ x, y, z }); // compiled, interpreted and batch agree
        EXPECT_TRUE(o.error.empty()) << o.error;
        const double cm = x < y ? -1.0 : x > y ? 1.0 : 0.0;
        const double an = cm == 0.0 ? cm : std::sin(x);
        const double orv = std::floor(x) != 0.0 ? std::floor(x) : std::cos(y);
        const double expected =
          ((((((((((((((1.0 / 3.0 + std::exp(0.5)) + std::log(3.0)) + std::sin(x)) +
                      std::tan(0.5)) +
                     std::asin(0.5)) +
                    std::acos(0.5)) +
                   std::atan(z)) +
                  std::atan2(y, x)) +
                 std::round(z)) +
                an) +
               orv) +
              (std::ceil(y) == 0.0 ? 1.0 : 0.0)) +
             rem_euclid(x, 3.0)) +
            std::floor(x));
        EXPECT_TRUE(same_bits(o.value, expected)) << o.value << " vs " << expected;
      }
    }
  }
}

TEST(VmOpcodes, UnknownOpcodesListTheKnownOnesAndExplainFidgetsRandomOps)
{
  ParseResult p = parse_vm("x var-x\nr cube x\n", "u.vm");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.diagnostics[0].message.find("recip exp ln"), std::string::npos)
    << p.diagnostics[0].message;
  EXPECT_NE(p.diagnostics[0].message.find("compare and or mod"), std::string::npos);
  p = parse_vm("x var-x\nr rand x\n", "u.vm");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.diagnostics[0].message.find("pseudo-random"), std::string::npos);
  p = parse_vm("x var-x\nr mod x\n", "u.vm");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.diagnostics[0].message.find("'mod' takes 2 operands, found 1"), std::string::npos);
  p = parse_vm("x var-x\nr round x x\n", "u.vm");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.diagnostics[0].message.find("'round' takes 1 operand, found 2"), std::string::npos);
}

TEST(VmOpcodes, HelperValuesAreNotNamesOfTheTape)
{
  // mod's hidden scalars ("mod~q", ...) cannot be referred to by a later instruction.
  const ParseResult p = parse_vm("x var-x\ny var-y\nr mod x y\ns neg mod~q\n", "h.vm");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.diagnostics[0].message.find("'mod~q' is not the name of an earlier instruction"),
    std::string::npos);
}

} // namespace
} // namespace frep
