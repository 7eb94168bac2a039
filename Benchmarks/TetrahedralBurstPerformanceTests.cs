#if SBD_PERFORMANCE_TESTING
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Jobs;
using Unity.Mathematics;
using Unity.PerformanceTesting;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// What users get from the mass-spring and FEM methods: one 1/60 s step as Burst code (<see cref="MassSpringStepJob"/>,
    /// <see cref="FemStepJob"/>, run on the main thread with <c>Run()</c>) of a 1 m Jelly cube of 8³ Kuhn-split cells
    /// (729 nodes, 3072 tetrahedra) resting on a floor plane, per integrator. The body is placed back at rest every
    /// <see cref="k_CycleSteps"/> steps, outside the timed region. Burst's safety checks are on in the Editor unless
    /// switched off in the Jobs ▸ Burst menu.
    /// </summary>
    public class TetrahedralBurstPerformanceTests
    {
        const int k_Cells = 8;
        const int k_WarmupCount = 5;
        const int k_MeasurementCount = 20;
        const int k_CycleSteps = 60;
        const float k_Dt = 1f / 60f;

        static TetrahedralMesh Cube() => BoxTetrahedra.Create(new float3(1f), new int3(k_Cells), float3.zero);

        static readonly float3 k_Start = new float3(0f, 0.52f, 0f);

        [Test, Performance]
        public void MassSpring_Step_8CubedCells_BurstJob([Values] MassSpringIntegrator integrator)
        {
            var issues = new List<ValidationIssue>();
            MassSpringModelData model = MassSpringModelData.FromMesh(Cube(), ElasticMaterial.Jelly, MassSpringBuildSettings.Default, issues, out _);
            Assert.That(model, Is.Not.Null, string.Join("\n", issues));
            MassSpringParameters parameters = MassSpringParameters.Default;
            parameters.Integrator = integrator;
            int n = model.ParticleCount;

            BlobAssetReference<MassSpringShapeBlob> shape = MassSpringShapeBlobFactory.Create(model.AsModel(), Allocator.Persistent);
            var colliders = new NativeArray<ColliderShape>(new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) }, Allocator.Persistent);
            var positions = new NativeArray<float3>(n, Allocator.Persistent);
            var velocities = new NativeArray<float3>(n, Allocator.Persistent);
            var status = new NativeArray<ParticleBodyStatus>(1, Allocator.Persistent);
            var report = new NativeArray<ParticleStepReport>(1, Allocator.Persistent);
            var job = new MassSpringStepJob
            {
                Shape = shape, Parameters = parameters, Colliders = colliders, DeltaTime = k_Dt, Positions = positions, Velocities = velocities,
                Scratch = new NativeArray<float3>(MassSpringState.ScratchPerParticle * n, Allocator.Persistent),
                SpringScratch = new NativeArray<float3>(MassSpringState.ScratchPerSpring * model.SpringCount, Allocator.Persistent),
                Status = status, Report = report,
            };
            try
            {
                StepCycleMeasure.Steps(() => job.Run(), () =>
                    {
                        var state = MassSpringState.FromScratch(positions.AsSpan(), velocities.AsSpan(), default, default);
                        MassSpringSolver.Initialize(shape.Value.AsModel(), state, k_Start, quaternion.identity, float3.zero, out ParticleBodyStatus placed);
                        status[0] = placed;
                    },
                    k_CycleSteps, $"MassSpring {integrator} x{n} Burst job step", k_WarmupCount, k_MeasurementCount);
                Assert.That(report[0].Stepped, Is.True, "the job stepped the body");
                Assert.That(report[0].Reset, Is.False, "no NaN-guard reset");
            }
            finally
            {
                job.Scratch.Dispose();
                job.SpringScratch.Dispose();
                positions.Dispose();
                velocities.Dispose();
                status.Dispose();
                report.Dispose();
                colliders.Dispose();
                shape.Dispose();
            }
        }

        [Test, Performance]
        public void Fem_Step_8CubedCells_BurstJob([Values] FemMaterialModel materialModel, [Values] FemIntegrator integrator)
        {
            var issues = new List<ValidationIssue>();
            FemModelData model = FemModelData.Create(Cube(), ElasticMaterial.Jelly, default, issues);
            Assert.That(model, Is.Not.Null, string.Join("\n", issues));
            FemParameters parameters = FemParameters.Default;
            parameters.Model = materialModel;
            parameters.Integrator = integrator;
            int n = model.RestPositions.Length, e = model.Elements.Length;

            BlobAssetReference<FemShapeBlob> shape = FemShapeBlobFactory.Create(model.AsModel(), Allocator.Persistent);
            var colliders = new NativeArray<ColliderShape>(new[] { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) }, Allocator.Persistent);
            var positions = new NativeArray<float3>(n, Allocator.Persistent);
            var velocities = new NativeArray<float3>(n, Allocator.Persistent);
            var rotations = new NativeArray<quaternion>(e, Allocator.Persistent);
            var status = new NativeArray<ParticleBodyStatus>(1, Allocator.Persistent);
            var report = new NativeArray<FemStepReport>(1, Allocator.Persistent);
            var job = new FemStepJob
            {
                Shape = shape, Parameters = parameters, Colliders = colliders, DeltaTime = k_Dt, Positions = positions, Velocities = velocities,
                Rotations = rotations,
                Scratch = new NativeArray<float3>(FemState.ScratchPerParticle * n, Allocator.Persistent),
                ElementScratch = new NativeArray<float3>(FemState.ScratchPerElement * e, Allocator.Persistent),
                Status = status, Report = report,
            };
            try
            {
                StepCycleMeasure.Steps(() => job.Run(), () =>
                    {
                        var state = new FemState(positions.AsSpan(), velocities.AsSpan(), rotations.AsSpan(), default, default, default, default, default, default);
                        FemSolver.Initialize(shape.Value.AsModel(), state, k_Start, quaternion.identity, float3.zero, out ParticleBodyStatus placed);
                        status[0] = placed;
                    },
                    k_CycleSteps, $"Fem {materialModel} {integrator} x{n} Burst job step", k_WarmupCount, k_MeasurementCount);
                Assert.That(report[0].Step.Stepped, Is.True, "the job stepped the body");
                Assert.That(report[0].Step.Reset, Is.False, "no NaN-guard reset");
            }
            finally
            {
                job.Scratch.Dispose();
                job.ElementScratch.Dispose();
                positions.Dispose();
                velocities.Dispose();
                rotations.Dispose();
                status.Dispose();
                report.Dispose();
                colliders.Dispose();
                shape.Dispose();
            }
        }
    }
}
#endif
