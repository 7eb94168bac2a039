using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The method study's body drivers: same mass for every method, pins hold, the hard cases stay finite.</summary>
    public class MethodStudyBodyTests
    {
        /// <summary>A 0.1 m rubber cube of 2³ cells (27 particles), nothing pinned.</summary>
        static MethodBodySetup Cube(bool pinBottom)
        {
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(0.1f), new int3(2, 2, 2), float3.zero);
            return new MethodBodySetup
            {
                Mesh = mesh,
                Material = ElasticMaterial.Rubber,
                Pinned = pinBottom ? StudyBox.NodesAt(mesh, 1, -0.05f, 1e-5f) : null,
                CalibrationLength = 0.1f,
                CalibrationLoad = ShapeMatchingCalibration.Load.Compression,
            };
        }

        static IEnumerable<IMethodBody> Bodies(MethodBodySetup setup)
        {
            foreach (MethodVariant v in MethodCatalog.Variants)
                yield return v.Create(setup, v.Knobs[0], 0.05f);
        }

        [TestCase(new[] { 1, 2, 3, 4, 5 }, 0, RunScope.Standard, new[] { 1, 3, 5 })]
        [TestCase(new[] { 1, 2, 3, 4 }, 0, RunScope.Standard, new[] { 1, 3, 4 })]
        [TestCase(new[] { 1, 2, 3, 4, 5, 6 }, 5, RunScope.Standard, new[] { 1, 3, 5 })]
        [TestCase(new[] { 1, 2, 3, 4, 5 }, 3, RunScope.Standard, new[] { 1, 2, 3 })]
        [TestCase(new[] { 1, 2, 3, 4, 5 }, 3, RunScope.Full, new[] { 1, 2, 3, 4, 5 })]
        [TestCase(new[] { 1, 2, 3, 4, 5 }, 0, RunScope.Quick, new[] { 0 })]
        public void DefaultRun_ThinsLongResolutionSweeps_ToEveryOtherAndTheFinest(int[] resolutions, int standardMax, RunScope scope, int[] expected)
        {
            var variant = new MethodVariant("fake", "substeps", new[] { 1 }, new[] { 1 }, (s, k, h) => null, resolutions);
            CollectionAssert.AreEqual(expected, variant.ResolutionsOf(scope, 10, standardMax));
        }

        [Test]
        public void EveryMethod_HasTheMassOfTheMaterial()
        {
            // ρ·V = 1100 kg/m³ × 1e-3 m³; lumped masses sum to it up to float32 round-off of 27 terms (~1e-6 relative).
            foreach (IMethodBody body in Bodies(Cube(false)))
            {
                double m = 0;
                foreach (float mi in body.Masses)
                    m += mi;
                Assert.That(m, Is.EqualTo(1.1).Within(1e-5), body.Family);
            }
        }

        [Test]
        public void EveryMethod_KeepsPinnedParticlesInPlace()
        {
            MethodBodySetup setup = Cube(true);
            foreach (IMethodBody body in Bodies(setup))
            {
                for (int k = 0; k < 30; k++)
                    body.Step(1f / 60f, new float3(0f, -9.81f, 0f), ReadOnlySpan<ColliderShape>.Empty);
                // An explicit integrator (symplectic Euler, Verlet) may be above its stable step at this knob; the guard then
                // resets the body, placing it again with its pins, and there is nothing left to check. Every other integrator
                // (implicit Euler, XPBD, shape matching, the hybrid) is stable at any step and must not be reset.
                bool conditionallyStable = body.Family.Contains("explicit") || body.Family.Contains("symplectic") || body.Family.Contains("Verlet");
                if (!conditionallyStable)
                    Assert.That(body.Resets, Is.EqualTo(0), body.Family);
                if (body.Resets > 0)
                    continue;
                // The mesh's nodes come first in every body (quadratic elements add their edge nodes after them).
                for (int i = 0; i < setup.Pinned.Length; i++)
                    if (setup.Pinned[i])
                        Assert.That(math.distance(body.Positions[i], body.RestPositions[i]), Is.EqualTo(0f), body.Family);
            }
        }

        [TestCase(HardCase.NanInput), TestCase(HardCase.Inverted), TestCase(HardCase.Flattened), TestCase(HardCase.HugeStep)]
        public void EveryMethod_StaysFiniteOnTheHardCases(HardCase hardCase)
        {
            // The cases are built as the stability study builds them (HardCases), on a free body at rest.
            foreach (IMethodBody body in Bodies(Cube(false)))
            {
                HardCases.Apply(body, hardCase);
                float dt = HardCases.StepLength(hardCase, 1f / 60f);
                for (int k = 0; k < 20; k++)
                    body.Step(dt, float3.zero, ReadOnlySpan<ColliderShape>.Empty);
                for (int i = 0; i < body.ParticleCount; i++)
                {
                    Assert.That(math.all(math.isfinite(body.Positions[i])), $"{body.Family}: {hardCase}");
                    // Bounded: within 10 body sizes of the origin (the guard resets beyond its own limits).
                    Assert.That(math.length(body.Positions[i]), Is.LessThan(1f), $"{body.Family}: {hardCase}");
                }
            }
        }

        [Test]
        public void ShapeMatching_WithoutPins_IsBitForBitTheSameModel()
        {
            // An all-false pin array must give exactly the model (and so the step) of no pin array.
            MethodBodySetup setup = Cube(false);
            float[] masses = setup.LumpedMasses();
            ClusterSet clusters = ClusterBuilder.Build(setup.Mesh.Positions, 0.1f);
            var a = ShapeMatchingModelData.Create(setup.Mesh.Positions, masses, clusters.Offsets, clusters.Particles, true);
            var b = ShapeMatchingModelData.Create(setup.Mesh.Positions, masses, clusters.Offsets, clusters.Particles, true,
                new bool[setup.Mesh.NodeCount]);
            Assert.That(b.InverseMasses, Is.Null);
            Assert.That(b.ClusterWeights, Is.EqualTo(a.ClusterWeights));
            Assert.That(b.ClusterRest, Is.EqualTo(a.ClusterRest));
        }

        [Test]
        public void ShapeMatchingCalibration_FrequencyScalesAsWaveSpeedOverLength()
        {
            // f = k √(E/ρ) / L: four times E, twice f; twice L, half f (float32 round-off only).
            var m = ElasticMaterial.Rubber;
            float f = ShapeMatchingCalibration.Frequency(m, 1f, 1f);
            Assert.That(f, Is.EqualTo(math.sqrt(1e6f / 1100f)).Within(1e-3f));
            m.YoungsModulus *= 4f;
            Assert.That(ShapeMatchingCalibration.Frequency(m, 2f, 1f), Is.EqualTo(f).Within(1e-3f));
        }
    }
}
