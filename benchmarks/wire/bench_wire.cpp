/* ----------------------------------------------------------------------
   NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
   spheropolyhedra coupled to elastic wires.

   Copyright (2026) the NSCD package developers. This software is
   distributed under the GNU General Public License, version 2, the
   licence of LAMMPS. See the LICENSE file in the top-level directory
   of the package.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: the NSCD package developers
------------------------------------------------------------------------- */

// Speed of the wire kernels and of a full subcycle, each with its error beside it.
#include "wire/elastic_forces.h"
#include "wire/soft_contact.h"
#include "wire/stability.h"
#include "wire/subcycle.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

using namespace nscd;
using namespace nscd::wire;

static void BM_BendingNode(benchmark::State &state)
{
  const Vec3 a(0, 0, 0), b(1, 0.1, 0), c(2, 0.3, 0.05);
  for (auto _ : state) benchmark::DoNotOptimize(bending_node_forces(1.0, a, b, c));
}
BENCHMARK(BM_BendingNode);

static void BM_SoftContact(benchmark::State &state)
{
  SoftContactLaw law{1e3, 1.0, 5e2, 0.5, 0.6, 0.4, SlipReset::ToDynamicLength};
  TangentialHistory h;
  const Vec3 n = Vec3(0.1, 0.2, 1).normalized();
  for (auto _ : state) benchmark::DoNotOptimize(soft_contact_force(law, n, 1e-3, Vec3(0.1, 0, -0.01), 1e-5, h));
}
BENCHMARK(BM_SoftContact);

// A free, initially wavy wire of N nodes (k_elo, k_rot, no damping) run for 2000
// substeps at half the stable step. Counters: ns per node per substep, and the relative
// change of total (kinetic + elastic) energy over the run, the integrator's error.
static void BM_WireSubcycle(benchmark::State &state)
{
  const int n = static_cast<int>(state.range(0));
  const double l = 0.01, m = 1e-4, k_elo = 10.0, k_rot = 1e-4;
  const WireTopology topology = open_chain_topology(n, l);
  const AxialLaw axial{k_elo, true};
  std::vector<Vec3> x0(n);
  for (int i = 0; i < n; ++i) x0[i] = Vec3(i * l * 0.999, 0.02 * std::sin(0.05 * i), 0);
  WireStiffness w;
  w.node_mass = m;
  w.element_length = l;
  w.k_elo = k_elo;
  w.k_rot = k_rot;
  const double dt = max_stable_wire_step(w);
  const auto coeff = gear5_corrector_coefficients(GearCorrector::ThreeSixteenths);
  GrainForceAccumulator grains;
  grains.reset(0);
  const SubcyclePlan plan{2000, dt};
  const auto energy = [&](const WireNodeSet &nodes) {
    std::vector<Vec3> x(n), f(n, Vec3::Zero());
    double kinetic = 0;
    for (int i = 0; i < n; ++i) {
      x[i] = nodes.state[i].position();
      kinetic += 0.5 * m * nodes.state[i].velocity(dt).squaredNorm();
    }
    return kinetic + add_elastic_forces(topology, axial, k_rot, x, f).total();
  };
  double drift = 0;
  for (auto _ : state) {
    state.PauseTiming();
    WireNodeSet nodes;
    nodes.reset(x0, m, dt);
    const double e0 = energy(nodes);
    state.ResumeTiming();
    run_subcycle(plan, coeff, nodes, grains,
                 [&](const SubstepInfo &, const std::vector<Vec3> &x, const std::vector<Vec3> &,
                     std::vector<Vec3> &f, GrainForceAccumulator &) {
                   add_elastic_forces(topology, axial, k_rot, x, f);
                 });
    state.PauseTiming();
    drift = energy(nodes) / e0 - 1.0;
    state.ResumeTiming();
  }
  state.counters["ns_per_node_step"] = benchmark::Counter(
      static_cast<double>(n) * plan.substeps * state.iterations(),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["rel_energy_change"] = drift;
}
BENCHMARK(BM_WireSubcycle)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// The elastic forces of one wavy chain of N nodes: add_elastic_forces against the prepared
// ElasticKernel (the same forces to the last bit: tests/unit/wire/test_elastic_forces.cpp).
// Counter: ns per node.
struct WavyChain {
  WireTopology topology;
  std::vector<Vec3> x, f;
  explicit WavyChain(int n) : topology(open_chain_topology(n, 0.01)), x(n), f(n, Vec3::Zero())
  {
    for (WireElement &e : topology.elements) e.law = AxialLaw{10.0, true};
    for (WireJoint &j : topology.joints) j.k_rot = 1e-4;
    for (int i = 0; i < n; ++i) x[i] = Vec3(i * 0.01 * 0.999, 0.02 * std::sin(0.05 * i), 0.01 * std::cos(0.03 * i));
  }
};

static void count_per_node(benchmark::State &state, std::size_t nodes)
{
  state.counters["ns_per_node"] = benchmark::Counter(static_cast<double>(nodes) * state.iterations(),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

static void BM_ElasticForces(benchmark::State &state)
{
  WavyChain chain(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(add_elastic_forces(chain.topology, chain.x, chain.f));
  count_per_node(state, chain.x.size());
}
BENCHMARK(BM_ElasticForces)->Arg(1000);

static void BM_ElasticKernel(benchmark::State &state)
{
  WavyChain chain(static_cast<int>(state.range(0)));
  ElasticKernel kernel;
  kernel.prepare(chain.topology);
  for (auto _ : state) benchmark::DoNotOptimize(kernel.add_forces(chain.x, chain.f, false));
  count_per_node(state, chain.x.size());
}
BENCHMARK(BM_ElasticKernel)->Arg(1000);

BENCHMARK_MAIN();
