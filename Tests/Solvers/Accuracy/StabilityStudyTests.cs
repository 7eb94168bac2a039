using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The stability study's tools: the step search against an exact bound, the bounded run, the hard-case outcomes.</summary>
    public class StabilityStudyTests
    {
        static MethodVariant Variant(string family)
        {
            foreach (MethodVariant v in MethodCatalog.Variants)
                if (v.Family == family)
                    return v;
            throw new ArgumentException(family);
        }

        [Test]
        public void LogBisection_BracketsAThresholdWithinTheFactor()
        {
            // A test that passes up to 1.234e-4: the answer passes and a failing value lies within the factor above it.
            const double threshold = 1.234e-4;
            double found = LogBisection.Largest(x => x <= threshold, 1e-6, 1.0, 1.05, out int evaluations);
            Assert.That(found, Is.LessThanOrEqualTo(threshold));
            Assert.That(found * 1.05, Is.GreaterThan(threshold));
            // log2(ln(1e6)/ln(1.05)) = 8.1: the upper end, then 9 halvings.
            Assert.That(evaluations, Is.EqualTo(10));
            Assert.That(LogBisection.Largest(x => true, 1e-6, 1.0, 1.05, out evaluations), Is.EqualTo(1.0));
            Assert.That(evaluations, Is.EqualTo(1));
        }

        [Test]
        public void StepSearch_FindsTheExplicitLimitOfAMassSpringBody()
        {
            // Symplectic Euler on the stiff cube (2³ cells, bottom pinned, ζ = 0.1) against MassSpringStability's
            // √(β² + 4/ω_max²) − β, exact for the network linearised at rest with stiffness-proportional damping. The start
            // is compressed by 0.1 % only, so the linearisation holds: the springs' geometric stiffness shifts ω_max by
            // O(ε) = 1e-3. The bisection returns a bounded step with an unbounded one within 1.05 above it, so
            // dt_max / bound ∈ [1/1.05, 1], widened by 1 % each side for the linearisation and the finite run length.
            var cube = new StabilityCube(StabilityCube.StiffMaterial, 0.1f, 2, 1e-3f);
            IMethodBody body = Variant("MS symplectic Euler").Create(cube.Pinned, 1, cube.CellSize);
            double found = LogBisection.Largest(dt => BoundedRun.Run(cube, body, (float)dt).Bounded,
                StableStepSearch.MinStep, StableStepSearch.MaxStep, StableStepSearch.Resolution, out _);
            double bound = cube.MassSpringExplicitStep;
            TestContext.WriteLine($"dt_max {found * 1e3:G4} ms, MassSpringStability {bound * 1e3:G4} ms, ratio {found / bound:F4}");
            Assert.That(found / bound, Is.InRange(0.99 / StableStepSearch.Resolution, 1.01));
        }

        [Test]
        public void StepSearch_ReportsAnExplicitMethodAsMonotone()
        {
            // The full search (with the runs at dt_max/2, /4 and ×2ᵏ) on a cheap explicit body: an explicit integrator's
            // stability is monotone in the step, and the search is not capped.
            var cube = new StabilityCube(StabilityCube.StiffMaterial, 0.1f, 2, 1e-3f);
            IMethodBody body = Variant("MS Verlet").Create(cube.Pinned, 1, cube.CellSize);
            StableStepResult r = StableStepSearch.Find(cube, body);
            Assert.That(r.Capped, Is.False);
            Assert.That(r.Monotone, Is.True);
            Assert.That(r.FailureAbove, Is.Not.EqualTo(UnboundedReason.None));
        }

        [TestCase("MS implicit Euler"), TestCase("FEM co-rotational implicit")]
        public void ImplicitEuler_IsBoundedAtOneSecond(string family)
        {
            // Implicit Euler is unconditionally stable (its amplification factor is 1/(1 + hβω² + h²ω²) in modulus ≤ 1
            // for every mode): the study's cube, 10 % compressed, stays bounded for 50 steps of 1 s at one substep.
            StabilityCube cube = MethodStudyStabilitySuite.Cube;
            IMethodBody body = Variant(family).Create(cube.Pinned, 1, cube.CellSize);
            BoundedRunResult r = BoundedRun.Run(cube, body, 1f);
            Assert.That(r.Reason, Is.EqualTo(UnboundedReason.None), family);
            Assert.That(r.Steps, Is.EqualTo(BoundedRun.MinSteps));
        }

        [Test]
        public void ShapeDeviation_IgnoresRigidMotionButSeesAMirror()
        {
            var cube = new StabilityCube(StabilityCube.StiffMaterial, 0.1f, 2);
            IMethodBody body = Variant("SM linear").Create(cube.Free, 1, cube.CellSize);
            quaternion turn = quaternion.AxisAngle(math.normalize(new float3(1f, 2f, 3f)), 1.1f);
            for (int i = 0; i < body.ParticleCount; i++)
                body.Positions[i] = new float3(0.3f, -0.2f, 0.1f) + math.mul(turn, body.RestPositions[i]);
            quaternion q = quaternion.identity;
            // A rigid motion: zero up to float32 round-off of positions ~0.4 m (~3e-8 m each, a few ulps summed).
            Assert.That(ShapeDeviation.Max(body, ref q), Is.LessThan(1e-6));
            // Mirrored through x = 0: no proper rotation undoes a reflection, so the deviation stays of the order of the
            // size (R = I leaves the x = ±L/2 faces L away); asserted far above the 5 % that counts as recovered.
            HardCases.Apply(body, HardCase.Inverted);
            double mirrored = ShapeDeviation.Max(body, ref q) / ShapeDeviation.Size(body);
            TestContext.WriteLine($"mirrored cube: deviation {mirrored:F4} sizes");
            Assert.That(mirrored, Is.GreaterThan(0.5));
        }

        [TestCase(0.01, 0, HardCaseOutcome.Recovers)]
        [TestCase(0.01, 1, HardCaseOutcome.Reset)]
        [TestCase(0.5, 0, HardCaseOutcome.Bounded)]
        [TestCase(0.5, 1, HardCaseOutcome.Bounded)]
        [TestCase(0.01, 2, HardCaseOutcome.Diverged)]
        [TestCase(3.0, 0, HardCaseOutcome.Diverged)]
        [TestCase(double.PositiveInfinity, 0, HardCaseOutcome.Diverged)]
        public void HardCaseOutcome_FollowsResetsAndDeviation(double deviation, int resets, HardCaseOutcome expected)
        {
            Assert.That(HardCaseRun.Classify(deviation, resets), Is.EqualTo(expected));
        }

        [Test]
        public void NanInput_IsResetByTheGuard()
        {
            // A NaN written into a position is caught before the step and the body reset to its rest shape, where an
            // unconditionally stable method stays: one reset, no deviation.
            var cube = new StabilityCube(StabilityCube.StiffMaterial, 0.1f, 2);
            IMethodBody body = Variant("SM linear").Create(cube.Free, 4, cube.CellSize);
            HardCaseResult r = HardCaseRun.Run(body, HardCase.NanInput, 1f / 60f, 1f, float3.zero);
            Assert.That(r.Outcome, Is.EqualTo(HardCaseOutcome.Reset));
            Assert.That(r.Resets, Is.EqualTo(1));
        }
    }
}
