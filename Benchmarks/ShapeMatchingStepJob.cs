using System;
using SoftBodyDynamics.Solvers;
using Unity.Burst;
using Unity.Collections;
using Unity.Entities;
using Unity.Jobs;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks
{
    /// <summary>
    /// One <see cref="ShapeMatchingSolver.Step"/> of one body as a Burst job, on the data a user's body lives in:
    /// the shape in a <see cref="ShapeMatchingShapeBlob"/> (the baked blob, read through <c>AsModel()</c> as the
    /// simulation system does) and the state in native arrays viewed as spans with
    /// <see cref="NativeArray{T}.AsSpan"/>. A thin wrapper: the parameters arrive whole, built by the shared
    /// scenario code, so the job does not change when their fields do. Compiled synchronously so the first timed
    /// run is already Burst code.
    /// </summary>
    [BurstCompile(CompileSynchronously = true)]
    public struct ShapeMatchingStepJob : IJob
    {
        /// <summary>The body's shape (rest positions, masses, clusters, rest data).</summary>
        public BlobAssetReference<ShapeMatchingShapeBlob> Shape;
        /// <summary>The body's parameters, as the scenario builds them.</summary>
        public ShapeMatchingParameters Parameters;
        /// <summary>Static colliders in world space.</summary>
        [ReadOnly] public NativeArray<ColliderShape> Colliders;
        /// <summary>Step length (s).</summary>
        public float DeltaTime;
        /// <summary>Particle positions (m, relative to the status's origin).</summary>
        public NativeArray<float3> Positions;
        /// <summary>Particle velocities (m/s).</summary>
        public NativeArray<float3> Velocities;
        /// <summary>Per-cluster state.</summary>
        public NativeArray<ClusterState> Clusters;
        /// <summary>Scratch of <see cref="ShapeMatchingState.ScratchPerParticle"/> × particles.</summary>
        public NativeArray<float3> Scratch;
        /// <summary>The body's status, one element, read and written by the step.</summary>
        public NativeArray<ParticleBodyStatus> Status;
        /// <summary>The report of the last step, one element.</summary>
        public NativeArray<ShapeMatchingStepReport> Report;

        public void Execute()
        {
            ref ShapeMatchingShapeBlob shape = ref Shape.Value;
            var state = ShapeMatchingState.FromScratch(Positions.AsSpan(), Velocities.AsSpan(), Clusters.AsSpan(), default,
                Scratch.AsSpan());
            ParticleBodyStatus status = Status[0];
            Report[0] = ShapeMatchingSolver.Step(shape.AsModel(), Parameters, Colliders.AsReadOnlySpan(), DeltaTime, state, ref status);
            Status[0] = status;
        }
    }

    /// <summary>
    /// Owns the native memory of one <see cref="ShapeMatchingStepJob"/> body: a blob of the model and native copies
    /// of a placed body's state. Dispose it.
    /// </summary>
    public sealed class ShapeMatchingJobBody : IDisposable
    {
        BlobAssetReference<ShapeMatchingShapeBlob> m_Shape;
        NativeArray<ColliderShape> m_Colliders;
        NativeArray<float3> m_Positions, m_Velocities, m_Scratch;
        NativeArray<ClusterState> m_Clusters;
        NativeArray<ParticleBodyStatus> m_Status;
        NativeArray<ShapeMatchingStepReport> m_Report;

        /// <summary>The job over this body's memory; run it as often as needed.</summary>
        public ShapeMatchingStepJob Job;

        /// <summary>Copies <paramref name="body"/> (model, parameters, placed state) into native memory.</summary>
        /// <param name="body">A placed body, e.g. <c>new ShapeMatchingInstance(model, parameters, position, rotation)</c>.</param>
        /// <param name="colliders">Static colliders in world space.</param>
        /// <param name="deltaTime">Step length (s).</param>
        public ShapeMatchingJobBody(Scenarios.ShapeMatchingInstance body, ColliderShape[] colliders, float deltaTime)
        {
            m_Shape = ShapeMatchingShapeBlobFactory.Create(body.Model, null, null, Allocator.Persistent);
            m_Colliders = new NativeArray<ColliderShape>(colliders, Allocator.Persistent);
            m_Positions = new NativeArray<float3>(body.Positions, Allocator.Persistent);
            m_Velocities = new NativeArray<float3>(body.Velocities, Allocator.Persistent);
            m_Clusters = new NativeArray<ClusterState>(body.Clusters, Allocator.Persistent);
            m_Scratch = new NativeArray<float3>(ShapeMatchingState.ScratchPerParticle * body.Model.ParticleCount, Allocator.Persistent);
            m_Status = new NativeArray<ParticleBodyStatus>(new[] { body.Status }, Allocator.Persistent);
            m_Report = new NativeArray<ShapeMatchingStepReport>(1, Allocator.Persistent);
            Job = new ShapeMatchingStepJob
            {
                Shape = m_Shape,
                Parameters = body.Parameters,
                Colliders = m_Colliders,
                DeltaTime = deltaTime,
                Positions = m_Positions,
                Velocities = m_Velocities,
                Clusters = m_Clusters,
                Scratch = m_Scratch,
                Status = m_Status,
                Report = m_Report,
            };
        }

        /// <summary>Writes a placed body's state (same model) back over this one's, e.g. to restart a cycle.</summary>
        public void Reset(Scenarios.ShapeMatchingInstance body)
        {
            m_Positions.CopyFrom(body.Positions);
            m_Velocities.CopyFrom(body.Velocities);
            m_Clusters.CopyFrom(body.Clusters);
            m_Status[0] = body.Status;
        }

        /// <summary>The report of the last run of <see cref="Job"/>.</summary>
        public ShapeMatchingStepReport LastReport => m_Report[0];

        public void Dispose()
        {
            if (m_Shape.IsCreated)
                m_Shape.Dispose();
            DisposeIfCreated(ref m_Colliders);
            DisposeIfCreated(ref m_Positions);
            DisposeIfCreated(ref m_Velocities);
            DisposeIfCreated(ref m_Scratch);
            DisposeIfCreated(ref m_Clusters);
            DisposeIfCreated(ref m_Status);
            DisposeIfCreated(ref m_Report);
        }

        static void DisposeIfCreated<T>(ref NativeArray<T> array) where T : struct
        {
            if (array.IsCreated)
                array.Dispose();
        }
    }
}
