// function_ref<R(Args...)>: a non-owning reference to something callable, two pointers wide (the object
// and a trampoline that calls it), as C++26's std::function_ref. Where a function takes a callback from a
// caller that outlives the call (a traversal's box test and leaf test), it replaces a template parameter,
// so the function can live in its own .cpp file, at one indirect call per use; unlike std::function it
// never allocates.
#pragma once
#include <memory>
#include <type_traits>
#include <utility>

namespace strahl {

template <class Signature>
class function_ref;

template <class R, class... Args>
class function_ref<R(Args...)> {
public:
    // Binds to f, which must outlive every call through this reference.
    template <class F>
        requires(!std::is_same_v<std::remove_cvref_t<F>, function_ref> && std::is_invocable_r_v<R, F&, Args...>)
    function_ref(F&& f) noexcept  // NOLINT: implicit on purpose, as std::function_ref
        : object_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
          call_([](void* object, Args... args) -> R {
              return (*static_cast<std::remove_reference_t<F>*>(object))(std::forward<Args>(args)...);
          }) {}

    R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

private:
    void* object_;
    R (*call_)(void*, Args...);
};

}  // namespace strahl
