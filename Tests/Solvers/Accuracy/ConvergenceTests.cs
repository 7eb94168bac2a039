using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The solver converges to the continuous model: its trajectory error against the float64 reference falls with
    /// the substep count at the order the substep has.
    /// </summary>
    public class ConvergenceTests
    {
        /// <summary>Substep counts checked at 1/60 s steps: ωh = 0.47 … 0.06 for the suite's 9 Hz body.</summary>
        static readonly int[] s_Substeps = { 2, 4, 8, 16 };

        /// <summary>
        /// Expected order 1: per substep the velocity is updated first and the position with the new velocity
        /// (symplectic Euler), the goals are those of the positions at the start of the substep, and the oscillator part
        /// has exact eigenvalues but an O(h) eigenvector error (the scheme's velocity lags half a substep), so the global
        /// error is C₁h + C₂h² + …; between h and h/2 the observed order is 1 + log₂((1 + r)/(1 + r/2)) with r = C₂h/C₁ = O(ωh).
        /// For ωh ≤ 0.5 the order must be ≥ <see cref="AccuracyTolerances.MinimumOrder"/> (0.8) at every halving and the error
        /// must fall at every step. The errors are ≥ 10⁴ times the reference's own (see <see cref="ContinuousReferenceTests"/>).
        /// </summary>
        [TestCaseSource(typeof(ContinuousReferenceTests), nameof(ContinuousReferenceTests.Families))]
        public void SolverError_FallsAtFirstOrder(ShapeMatchingMode mode, ShapeMatchingClusterLayout layout)
        {
            ConvergenceStudy study = ConvergenceStudy.For(mode, layout);
            double[] errors = Errors(study.Release, study.Release.Parameters, study.Reference);
            for (int k = 1; k < errors.Length; k++)
            {
                double order = Math.Log(errors[k - 1] / errors[k], 2);
                TestContext.WriteLine($"{s_Substeps[k - 1]} → {s_Substeps[k]} substeps: error {errors[k - 1]:E3} → {errors[k]:E3}, order {order:F3}");
                Assert.That(errors[k], Is.LessThan(errors[k - 1]));
                Assert.That(order, Is.GreaterThanOrEqualTo(AccuracyTolerances.MinimumOrder));
            }
        }

        /// <summary>
        /// The test can fail: a solver whose ω is 2 % off the reference's (a time rule that is not exact, e.g. the old
        /// per-frame stiffness, is off by far more) converges to a different trajectory, so its error stops falling and
        /// the observed order collapses below the threshold.
        /// </summary>
        [Test]
        public void WrongFrequency_FailsTheOrderCheck()
        {
            ConvergenceStudy study = ConvergenceStudy.For(ShapeMatchingMode.Linear, ShapeMatchingClusterLayout.Overlapping);
            ShapeMatchingParameters wrong = study.Release.Parameters;
            wrong.Frequency *= 1.02f;
            double[] errors = Errors(study.Release, wrong, study.Reference);
            double last = Math.Log(errors[errors.Length - 2] / errors[errors.Length - 1], 2);
            Assert.That(last, Is.LessThan(AccuracyTolerances.MinimumOrder));
        }

        static double[] Errors(ConvergenceRelease release, ShapeMatchingParameters parameters, Vector3d[][] reference)
        {
            var errors = new double[s_Substeps.Length];
            for (int k = 0; k < s_Substeps.Length; k++)
            {
                var run = new ConvergenceRelease(release.Model, parameters, release.Start);
                errors[k] = run.Error(run.SolverTrajectory(s_Substeps[k], out int resets), reference);
                Assert.That(resets, Is.Zero);
            }
            return errors;
        }
    }
}
