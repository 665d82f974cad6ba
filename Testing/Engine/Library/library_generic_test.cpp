// call_generic instantiated with a scalar type of our own whose comparisons return a wrapper
// condition (no conversion to bool): any `if`/`?:`/loop on a value in the generic library would
// not compile. For every generic function, random and special arguments must give exactly the
// values and array effects of library::call.
#include "library_test_support.h"

#include "Library/detail/library_generic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace wrapped
{

struct Cond
{
  bool v;
};

struct Num
{
  double v = 0.0;
  Num() = default;
  Num(double d) // implicit, like the compiler's Expr
    : v(d)
  {
  }
};

inline Num operator+(Num a, Num b)
{
  return a.v + b.v;
}
inline Num operator-(Num a, Num b)
{
  return a.v - b.v;
}
inline Num operator*(Num a, Num b)
{
  return a.v * b.v;
}
inline Num operator/(Num a, Num b)
{
  return a.v / b.v;
}
inline Num operator-(Num a)
{
  return -a.v;
}
inline Cond operator<(Num a, Num b)
{
  return { a.v < b.v };
}
inline Cond operator<=(Num a, Num b)
{
  return { a.v <= b.v };
}
inline Cond operator>(Num a, Num b)
{
  return { a.v > b.v };
}
inline Cond operator>=(Num a, Num b)
{
  return { a.v >= b.v };
}
inline Num select(Cond c, Num a, Num b)
{
  return c.v ? a : b;
}
inline Cond logical_and(Cond a, Cond b)
{
  return { a.v && b.v };
}
inline Cond logical_or(Cond a, Cond b)
{
  return { a.v || b.v };
}
inline Cond logical_not(Cond a)
{
  return { !a.v };
}

#define WRAPPED_UNARY(name)                                                                        \
  inline Num name(Num a)                                                                           \
  {                                                                                                \
    return std::name(a.v);                                                                         \
  }
WRAPPED_UNARY(acos)
WRAPPED_UNARY(asin)
WRAPPED_UNARY(atan)
WRAPPED_UNARY(ceil)
WRAPPED_UNARY(cos)
WRAPPED_UNARY(cosh)
WRAPPED_UNARY(exp)
WRAPPED_UNARY(fabs)
WRAPPED_UNARY(floor)
WRAPPED_UNARY(log)
WRAPPED_UNARY(log10)
WRAPPED_UNARY(sin)
WRAPPED_UNARY(sinh)
WRAPPED_UNARY(sqrt)
WRAPPED_UNARY(tan)
WRAPPED_UNARY(tanh)
WRAPPED_UNARY(trunc)
#undef WRAPPED_UNARY
inline Num atan2(Num a, Num b)
{
  return std::atan2(a.v, b.v);
}
inline Num pow(Num a, Num b)
{
  return std::pow(a.v, b.v);
}
inline Num fmod(Num a, Num b)
{
  return std::fmod(a.v, b.v);
}

struct Context
{
  int aborts = 0;
  void abort_if(Cond c, const char*) { aborts += c.v ? 1 : 0; }
};

} // namespace wrapped

namespace frep::library::test
{
namespace
{

using F = FunctionId;

/// Random arguments for one call: reals from a mix of ordinary and special values, arrays of
/// size 3 mostly (point arrays), sometimes other sizes (skeleton lists, attribute tables).
struct RandomCall
{
  std::vector<std::vector<double>> arrays;
  std::vector<double> reals;
};

double random_value(std::mt19937& rng)
{
  static const double specials[] = {
    0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 1e-7, -1e-7, 180.0, 400.0, 4.0, 3.0, 1e300, -1e300
  };
  std::uniform_int_distribution<int> pick(0, 9);
  if (pick(rng) < 2)
  {
    std::uniform_int_distribution<std::size_t> which(0, std::size(specials) - 1);
    return specials[which(rng)];
  }
  std::uniform_real_distribution<double> uniform(-3.0, 3.0);
  return uniform(rng);
}

RandomCall make_random_call(const FunctionInfo& info, std::mt19937& rng)
{
  RandomCall c;
  std::uniform_int_distribution<int> size_pick(0, 9);
  std::uniform_int_distribution<int> other_size(1, 12);
  for (int i = 0; i < info.arity; ++i)
  {
    if (info.kinds[i] == ArgKind::Array)
    {
      const int size = size_pick(rng) < 6 ? 3 : other_size(rng);
      std::vector<double> a(size);
      for (double& v : a)
      {
        v = random_value(rng);
      }
      c.arrays.push_back(std::move(a));
      c.reals.push_back(0.0);
    }
    else
    {
      c.arrays.emplace_back();
      c.reals.push_back(random_value(rng));
    }
  }
  return c;
}

TEST(LibraryGeneric, WrappedScalarMatchesDoubleForEveryGenericFunction)
{
  std::mt19937 rng(20240601);
  int generic_count = 0;
  for (const FunctionInfo& info : function_table())
  {
    if (info.builtin || !is_generic(info.id))
    {
      continue;
    }
    ++generic_count;
    for (int trial = 0; trial < 400; ++trial)
    {
      const RandomCall rc = make_random_call(info, rng);

      // double reference through library::call
      std::vector<std::vector<double>> d_arrays = rc.arrays;
      std::vector<Arg<double>> d_args(info.arity);
      // wrapped run through call_generic
      std::vector<std::vector<wrapped::Num>> w_arrays(info.arity);
      std::vector<Arg<wrapped::Num>> w_args(info.arity);
      for (int i = 0; i < info.arity; ++i)
      {
        d_args[i].real = rc.reals[i];
        w_args[i].real = rc.reals[i];
        if (info.kinds[i] == ArgKind::Array)
        {
          d_args[i].array = std::span<double>(d_arrays[i]);
          for (double v : rc.arrays[i])
          {
            w_arrays[i].push_back(v);
          }
          w_args[i].array = std::span<wrapped::Num>(w_arrays[i]);
        }
      }
      DoubleContext d_context;
      const double expected = call(info.id, d_args, d_context);
      wrapped::Context w_context;
      const std::optional<wrapped::Num> got =
        call_generic<wrapped::Num, wrapped::Context>(info.id, w_args, w_context);
      ASSERT_TRUE(got.has_value()) << info.spelling;
      EXPECT_PRED2(same_bits, expected, got->v) << info.spelling << " trial " << trial;
      EXPECT_FALSE(d_context.abort_message.has_value()) << info.spelling;
      for (int i = 0; i < info.arity; ++i)
      {
        for (std::size_t k = 0; k < d_arrays[i].size(); ++k)
        {
          EXPECT_PRED2(same_bits, d_arrays[i][k], w_arrays[i][k].v)
            << info.spelling << " argument " << i << " item " << k << " trial " << trial;
        }
      }
    }
  }
  // 24 primitives, 2 blends, 14 transformations and space maps, 9 distance functions and 15
  // attribute functions are generic (the other 20 library functions are double-only)
  EXPECT_EQ(generic_count, 64);
}

TEST(LibraryGeneric, DoubleOnlyFunctionsAreNotExpanded)
{
  std::vector<Arg<double>> args(5);
  DoubleContext context;
  EXPECT_FALSE(call_generic<double>(F::DEllipsoid, std::span(args), context).has_value());
  std::vector<Arg<double>> wrong(2);
  EXPECT_FALSE(call_generic<double>(F::Sphere, std::span(wrong), context).has_value());
}

} // namespace
} // namespace frep::library::test
