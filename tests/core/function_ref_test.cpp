// FunctionRef (core/function_ref.h): calls the callable it refers to, mutable or const,
// without copying it.
#include "skylit/core/function_ref.h"

#include <gtest/gtest.h>

namespace skylit {
namespace {

double apply_twice(FunctionRef<double(double)> f, double x) { return f(f(x)); }

TEST(FunctionRef, CallsMutableAndConstCallablesInPlace) {
  int calls = 0;
  auto counting = [&calls](double x) {
    ++calls;
    return x + 1;
  };
  EXPECT_EQ(apply_twice(counting, 1.0), 3.0);
  EXPECT_EQ(calls, 2);

  struct Scale {
    double factor;
    double operator()(double x) const { return factor * x; }
  };
  const Scale triple{3};
  EXPECT_EQ(apply_twice(triple, 2.0), 18.0);

  struct Accumulate {  // state kept in the referred object, not in a copy
    double sum = 0;
    double operator()(double x) { return sum += x; }
  } accumulate;
  apply_twice(accumulate, 1.0);
  EXPECT_EQ(accumulate.sum, 2.0);
}

}  // namespace
}  // namespace skylit
