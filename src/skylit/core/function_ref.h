// A non-owning reference to a callable, for callbacks that should not make their callee
// a template (it stays compiled once, in its own file) yet need no allocation, no void*
// context and no casts at the call site: what C++26 calls std::function_ref, cut to what
// we use. The callable must outlive the FunctionRef (pass it straight to the call).
#pragma once

#include <memory>
#include <type_traits>
#include <utility>

namespace skylit {

template <typename Signature>
class FunctionRef;

template <typename R, typename... Args>
class FunctionRef<R(Args...)> {
 public:
  // The constraint keeps copies and moves of a FunctionRef away from this constructor
  // (written with enable_if, which clang-format 14 and clang-tidy 14 read, unlike requires).
  template <typename F, typename = std::enable_if_t<!std::is_same_v<std::remove_cvref_t<F>, FunctionRef> &&
                                                    std::is_invocable_r_v<R, F&, Args...>>>
  FunctionRef(F&& f) noexcept {  // NOLINT(google-explicit-constructor): it stands for the callable
    using Callable = std::remove_reference_t<F>;
    // A const callable is kept as const: the union's member matches its constness.
    if constexpr (std::is_const_v<Callable>) {
      object_.read_only = std::addressof(f);
      call_ = [](Object o, Args... args) -> R {
        return (*static_cast<Callable*>(o.read_only))(std::forward<Args>(args)...);
      };
    } else {
      object_.mutable_ = std::addressof(f);
      call_ = [](Object o, Args... args) -> R {
        return (*static_cast<Callable*>(o.mutable_))(std::forward<Args>(args)...);
      };
    }
  }

  R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

 private:
  union Object {
    void* mutable_;
    const void* read_only;
  };
  Object object_;
  R (*call_)(Object, Args...);
};

}  // namespace skylit
