#pragma once
// Point-to-node sums on several threads that give the same bits on every run with the same
// thread count. Each thread sums its static share of the points into a buffer of its own, then
// the buffers are added node by node in thread order. Atomic adds (or OpenMP's reduction
// clause) would make the order of the additions, and so their rounding, depend on which thread
// arrives first: two runs of the same case would differ in the last bits, and a chaotic flow
// grows such differences into visibly different results. Internal to the solver library.
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace lituya::solver::detail {

inline void set_zero(std::vector<double>& values) {
  std::fill(values.begin(), values.end(), 0.0);
}
template <class Vec>
void set_zero(std::vector<Vec>& values) {
  std::fill(values.begin(), values.end(), Vec::Zero());
}

// `Sums` is a struct of nodal arrays with `assign(n_nodes)` (sized and zeroed).
template <class Sums>
class NodalScatter {
 public:
  // One buffer per thread; buffer 0 holds the result.
  void allocate(int threads, std::size_t n_nodes) {
    buffers_.resize(static_cast<std::size_t>(std::max(1, threads)));
    for (Sums& b : buffers_) b.assign(n_nodes);
    n_nodes_ = n_nodes;
  }
  int threads() const { return static_cast<int>(buffers_.size()); }
  Sums& sums() { return buffers_.front(); }
  const Sums& sums() const { return buffers_.front(); }

  // `fields(Sums&)` returns std::tie(...) of the arrays this pass fills (they are zeroed
  // first; the others keep their values); `body(Sums&, k)` adds item k's contributions.
  template <class Fields, class Body>
  void run(std::size_t n_items, Fields fields, Body body) {
#pragma omp parallel num_threads(threads())
    {
      // The team may be smaller than asked for (OMP_DYNAMIC): only its buffers take part.
      const int team = omp_get_num_threads();
      Sums& mine = buffers_[static_cast<std::size_t>(omp_get_thread_num())];
      std::apply([](auto&... field) { (set_zero(field), ...); }, fields(mine));
#pragma omp for schedule(static)
      for (std::size_t k = 0; k < n_items; ++k) body(mine, k);
      if (team > 1) {
#pragma omp for schedule(static)
        for (std::size_t i = 0; i < n_nodes_; ++i)
          for (int t = 1; t < team; ++t)
            add_at(fields(buffers_[0]), fields(buffers_[static_cast<std::size_t>(t)]), i);
      }
    }
  }

 private:
  template <class Into, class From>
  static void add_at(Into into, From from, std::size_t i) {
    add_at(into, from, i, std::make_index_sequence<std::tuple_size_v<Into>>{});
  }
  template <class Into, class From, std::size_t... k>
  static void add_at(Into into, From from, std::size_t i, std::index_sequence<k...>) {
    ((std::get<k>(into)[i] += std::get<k>(from)[i]), ...);
  }

  std::vector<Sums> buffers_;
  std::size_t n_nodes_ = 0;
};

// One nodal scalar field (the pressure projection's sums).
struct ScalarSums {
  std::vector<double> value;
  void assign(std::size_t n) { value.assign(n, 0.0); }
};

// sum over k of term(k), on `threads` threads, with partial sums per thread added in thread
// order: the same bits on every run with the same thread count (an OpenMP + reduction adds
// the partial sums in the order the threads finish).
template <class Term>
double ordered_sum(int threads, std::size_t n, Term term) {
  std::vector<double> partial(static_cast<std::size_t>(std::max(1, threads)), 0.0);
#pragma omp parallel num_threads(threads)
  {
    double sum = 0;
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n; ++k) sum += term(k);
    partial[static_cast<std::size_t>(omp_get_thread_num())] = sum;
  }
  double total = 0;
  for (double s : partial) total += s;
  return total;
}

}  // namespace lituya::solver::detail
