// The machinery behind geometry/shapes.h: a list of shape templates, and one
// array per shape of the list in a given scalar type, numbered through in
// the list's order. Code that handles "every bounded shape" walks the list,
// so a new shape needs no change there.
//
// A shape S<T> of the list provides, as Sphere does:
//   Lanes<T> intersect(const RayPacket<T>&, T t_min, Lanes<T> t_max) const
//   Aabb bounds() const                       (in double, not yet padded)
//   PrimitiveSurface<T> surface() const       (geometry/surface.h)
//   template <typename U> S<U> in() const     (the same shape in U)
//   int material
#pragma once

#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

#include "core/vec.h"

namespace fh {

template <template <typename> class... Shapes>
struct ShapeList {};

template <typename T, typename List>
class ShapeArrays;

template <typename T, template <typename> class... Shapes>
class ShapeArrays<T, ShapeList<Shapes...>> {
public:
    static constexpr std::size_t kKinds = sizeof...(Shapes);

    template <template <typename> class S>
    std::vector<S<T>>& of() { return std::get<std::vector<S<T>>>(arrays_); }
    template <template <typename> class S>
    const std::vector<S<T>>& of() const { return std::get<std::vector<S<T>>>(arrays_); }

    // fn(array) for each shape's array, in the list's order.
    template <typename Fn>
    void each_array(Fn&& fn) const { std::apply([&](const auto&... a) { (fn(a), ...); }, arrays_); }
    template <typename Fn>
    void each_array(Fn&& fn) { std::apply([&](auto&... a) { (fn(a), ...); }, arrays_); }

    // fn(shape) for every shape, in numbering order.
    template <typename Fn>
    void each(Fn&& fn) const {
        each_array([&](const auto& a) {
            for (const auto& s : a) fn(s);
        });
    }

    std::size_t size() const {
        std::size_t n = 0;
        each_array([&](const auto& a) { n += a.size(); });
        return n;
    }
    bool empty() const { return size() == 0; }

    // fn(shape i), counting through the arrays in the list's order (i < size()).
    template <typename Fn>
    FH_HOT_INLINE decltype(auto) visit(std::size_t i, Fn&& fn) const { return visit_from<0>(i, fn); }

    // For a list of ids in increasing order, from list[k] on: fn(shape, id)
    // for each that is a shape (id < end, end = size()), kind by kind -- one
    // loop per kind, no test of the kind per shape -- leaving k at the first
    // id past them. fn returns true to stop; so does this. Past the first
    // kind one comparison skips the others when the scene has none: a kind
    // the scene does not use costs it nothing.
    template <typename Fn>
    FH_HOT_INLINE bool for_each_listed(const std::vector<int>& list, std::size_t& k, int end, Fn&& fn) const {
        std::size_t first = 0;  // the id of the current kind's first shape
        if (run_of(std::get<0>(arrays_), first, list, k, fn)) return true;
        if (first == std::size_t(end)) return false;
        return listed_runs(list, k, first, fn, std::make_index_sequence<kKinds>{});
    }

    // The same shapes in scalar type U.
    template <typename U>
    ShapeArrays<U, ShapeList<Shapes...>> in() const {
        ShapeArrays<U, ShapeList<Shapes...>> out;
        (convert<Shapes, U>(out), ...);
        return out;
    }

private:
    template <std::size_t K, typename Fn>
    FH_HOT_INLINE decltype(auto) visit_from(std::size_t i, Fn& fn) const {
        const auto& a = std::get<K>(arrays_);
        if constexpr (K + 1 == kKinds) {
            return fn(a[i]);
        } else {
            if (i < a.size()) return fn(a[i]);
            return visit_from<K + 1>(i - a.size(), fn);
        }
    }
    // (Not std::apply: GCC does not inline it into the walk.)
    template <typename Fn, std::size_t... K>
    FH_HOT_INLINE bool listed_runs(const std::vector<int>& list, std::size_t& k, std::size_t first, Fn& fn,
                                   std::index_sequence<K...>) const {
        bool stop = false;
        ((stop = stop || (K > 0 && run_of(std::get<K>(arrays_), first, list, k, fn))), ...);
        return stop;
    }
    template <typename Array, typename Fn>
    static FH_HOT_INLINE bool run_of(const Array& a, std::size_t& first, const std::vector<int>& list, std::size_t& k,
                                     Fn& fn) {
        const std::size_t end = first + a.size();
        for (; k < list.size() && std::size_t(list[k]) < end; ++k)
            if (fn(a[std::size_t(list[k]) - first], list[k])) return true;
        first = end;
        return false;
    }
    template <template <typename> class S, typename U>
    void convert(ShapeArrays<U, ShapeList<Shapes...>>& out) const {
        for (const S<T>& s : of<S>()) out.template of<S>().push_back(s.template in<U>());
    }

    std::tuple<std::vector<Shapes<T>>...> arrays_;
};

}  // namespace fh
