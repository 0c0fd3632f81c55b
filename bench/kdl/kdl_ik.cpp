// Orocos KDL side of the ik benchmark (bench/RobotControl.Bench/Ik/KdlRunner.cs writes the input, reads the output).
// Input (text): "rows R", R lines "alpha_rad a_m d_m theta_offset_rad joint(0|1)", "joints n", n lines "min max",
// "seed q1..qn", "targets T", T lines "px py pz r00 r01 r02 r10 r11 r12 r20 r21 r22" (metres, rotation row-major).
// Passes (optional third argument): every target is solved that many times, one output line each.
// Output: one line per solver, pass and target: "<solver> <index> <return code> <microseconds> q1..qn", then per solver
// "cpu <solver> <mean thread-CPU microseconds per solve>".
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>
#include <kdl/frames.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

struct Problem {
    KDL::Chain chain;
    KDL::JntArray qMin, qMax, seed;
    std::vector<KDL::Frame> targets;
};

bool Read(const char* path, Problem& p) {
    std::ifstream in(path);
    std::string word;
    int rows = 0;
    if (!(in >> word >> rows) || word != "rows") return false;
    for (int i = 0; i < rows; i++) {
        double alpha, a, d, theta;
        int joint;
        in >> alpha >> a >> d >> theta >> joint;
        // Standard DH: T = Rz(theta) Tz(d) Tx(a) Rx(alpha); the joint turns about the segment's base z.
        p.chain.addSegment(KDL::Segment(KDL::Joint(joint ? KDL::Joint::RotZ : KDL::Joint::Fixed),
                                        KDL::Frame::DH(a, alpha, d, theta)));
    }
    int n = 0;
    in >> word >> n;
    p.qMin.resize(n);
    p.qMax.resize(n);
    p.seed.resize(n);
    for (int i = 0; i < n; i++) in >> p.qMin(i) >> p.qMax(i);
    in >> word;
    for (int i = 0; i < n; i++) in >> p.seed(i);
    int count = 0;
    in >> word >> count;
    p.targets.reserve(count);
    for (int t = 0; t < count; t++) {
        double x, y, z, r[9];
        in >> x >> y >> z;
        for (double& v : r) in >> v;
        p.targets.emplace_back(KDL::Rotation(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]), KDL::Vector(x, y, z));
    }
    return static_cast<bool>(in) && static_cast<int>(p.chain.getNrOfJoints()) == n;
}

template <typename Solver>
void RunAll(const char* name, Solver& solver, const Problem& p, int passes, FILE* out) {
    const unsigned n = p.chain.getNrOfJoints();
    KDL::JntArray q(n);
    // Warm up caches and the allocator as the C# side does.
    for (size_t t = 0; t < p.targets.size() && t < 50; t++) solver.CartToJnt(p.seed, p.targets[t], q);
    for (int pass = 0; pass < passes; pass++)
    for (size_t t = 0; t < p.targets.size(); t++) {
        auto start = std::chrono::steady_clock::now();
        int rc = solver.CartToJnt(p.seed, p.targets[t], q);
        auto stop = std::chrono::steady_clock::now();
        double us = std::chrono::duration<double, std::micro>(stop - start).count();
        std::fprintf(out, "%s %zu %d %.4f", name, t, rc, us);
        for (unsigned i = 0; i < n; i++) std::fprintf(out, " %.17g", q(i));
        std::fputc('\n', out);
    }
    // Second, untimed pass: thread CPU time per solve (excludes time descheduled on a loaded machine).
    timespec a{}, b{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
    for (size_t t = 0; t < p.targets.size(); t++) solver.CartToJnt(p.seed, p.targets[t], q);
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
    double cpu = ((b.tv_sec - a.tv_sec) * 1e6 + (b.tv_nsec - a.tv_nsec) * 1e-3) / static_cast<double>(p.targets.size());
    std::fprintf(out, "cpu %s %.4f\n", name, cpu);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4) {
        std::cerr << "usage: kdl_ik <input> <output> [passes]\n";
        return 2;
    }
    Problem p;
    if (!Read(argv[1], p)) {
        std::cerr << "kdl_ik: cannot read " << argv[1] << "\n";
        return 2;
    }
    const int passes = argc == 4 ? std::max(1, std::atoi(argv[3])) : 1;
    FILE* out = std::fopen(argv[2], "w");
    if (!out) return 2;

    // LMA: task-space weights sized for a 0.2 m arm (1 rad ~ 0.1 m), eps on the weighted error, default 500 iterations.
    Eigen::Matrix<double, 6, 1> weights;
    weights << 1, 1, 1, 0.1, 0.1, 0.1;
    KDL::ChainIkSolverPos_LMA lma(p.chain, weights, 1e-7, 500, 1e-15);
    RunAll("kdl_lma", lma, p, passes, out);

    // NR_JL: Newton-Raphson with joint limits over the SVD pseudo-inverse velocity solver, 1e-5 (m, rad), 100 iterations.
    KDL::ChainFkSolverPos_recursive fk(p.chain);
    KDL::ChainIkSolverVel_pinv vel(p.chain);
    KDL::ChainIkSolverPos_NR_JL nrjl(p.chain, p.qMin, p.qMax, fk, vel, 100, 1e-5);
    RunAll("kdl_nr_jl", nrjl, p, passes, out);

    std::fclose(out);
    return 0;
}
