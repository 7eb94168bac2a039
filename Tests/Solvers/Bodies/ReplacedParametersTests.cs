using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The run-time rule for invalid parameters: the default (or the limit), and the step says so.</summary>
    public class ReplacedParametersTests
    {
        /// <summary>A negative frequency and NaN are the same mistake: both run at the default frequency, not at 0 Hz (which would let the body collapse).</summary>
        [Test]
        public void InvalidFrequency_RunsAtTheDefault_WhateverTheMistake()
        {
            foreach (float bad in new[] { -1f, float.NaN, float.NegativeInfinity })
            {
                ShapeMatchingParameters p = ShapeMatchingParameters.Default;
                p.Frequency = bad;
                Assert.That(p.Sanitized().Frequency, Is.EqualTo(ShapeMatchingParameters.Default.Frequency), $"frequency {bad}");
                p = ShapeMatchingParameters.Default;
                p.DampingRatio = bad;
                Assert.That(p.Sanitized().DampingRatio, Is.EqualTo(ShapeMatchingParameters.Default.DampingRatio), $"damping ratio {bad}");
            }
            ShapeMatchingParameters high = ShapeMatchingParameters.Default;
            high.Frequency = float.PositiveInfinity;
            Assert.That(high.Sanitized().Frequency, Is.EqualTo(ShapeMatchingParameters.MaxFrequency), "beyond the limit: the limit");
        }

        [Test]
        public void ShapeMatchingStep_ReportsReplacedParameters()
        {
            ShapeMatchingModelData model = LatticeBody.Create(new int3(3, 3, 3), 0.1f, 3, 1f, false);
            ShapeMatchingParameters p = ShapeMatchingParameters.Default;
            var body = new ShapeMatchingInstance(model, p, float3.zero, quaternion.identity);
            Assert.That(body.Step(1f / 60f).ParametersReplaced, Is.False, "valid parameters");
            body.Parameters.Frequency = -3f;
            Assert.That(body.Step(1f / 60f).ParametersReplaced, Is.True, "a negative frequency");
        }

        [Test]
        public void FemStep_ReportsReplacedParameters()
        {
            FemModelData data = FemTestBodies.Bake(FemTestBodies.Box(1, 1, 1, new float3(0.1f)), ElasticMaterial.Jelly);
            var body = new FemTestBody(data, FemParameters.Default);
            Assert.That(body.Step(1f / 60f).Step.ParametersReplaced, Is.False, "valid parameters");
            body.Parameters.CgTolerance = float.NaN;
            Assert.That(body.Step(1f / 60f).Step.ParametersReplaced, Is.True, "a NaN tolerance");
        }

        [Test]
        public void MassSpringStep_ReportsReplacedParameters()
        {
            MethodBodySetup setup = new MethodBodySetup
            {
                Mesh = BoxTetrahedra.Create(new float3(0.1f), new int3(1), float3.zero),
                Material = ElasticMaterial.Jelly,
            };
            MassSpringModelData model = MassSpringModelData.FromMesh(setup.Mesh, setup.Material, MassSpringBuildSettings.Default,
                new System.Collections.Generic.List<ValidationIssue>(), out _);
            int n = model.RestPositions.Length;
            MassSpringParameters p = MassSpringParameters.Default;
            var positions = new float3[n];
            var velocities = new float3[n];
            var state = new MassSpringState(positions, velocities, new float3[MassSpringState.ScratchPerParticle * n],
                new float3[MassSpringState.ScratchPerSpring * model.SpringCount]);
            MassSpringSolver.Initialize(model.AsModel(), state, float3.zero, quaternion.identity, float3.zero, out ParticleBodyStatus status);
            Assert.That(MassSpringSolver.Step(model.AsModel(), p, ReadOnlySpan<ColliderShape>.Empty, 1f / 60f, state, ref status, 64).ParametersReplaced,
                Is.False, "valid parameters");
            p.Body.Substeps = 0;
            Assert.That(MassSpringSolver.Step(model.AsModel(), p, ReadOnlySpan<ColliderShape>.Empty, 1f / 60f, state, ref status, 64).ParametersReplaced,
                Is.True, "zero substeps");
        }
    }
}
