using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One shape-matching body on managed arrays, for tests and benchmarks: the same model / state
    /// views the ECS job builds from blobs and buffers, and the same <see cref="ShapeMatchingSolver.Step"/>.
    /// </summary>
    public sealed class ShapeMatchingInstance
    {
        public readonly ShapeMatchingModelData Model;
        public ShapeMatchingParameters Parameters;
        public readonly float3[] Positions;
        public readonly float3[] Velocities;
        public readonly ClusterState[] Clusters;
        public readonly float3x3[] QuadraticInverse;
        public ParticleBodyStatus Status;
        readonly float3[] m_Predicted, m_Goals, m_Normals;

        /// <param name="perInstanceQuadratic">Allocate the per-instance quadratic inverses plastic flow needs in quadratic mode.</param>
        public ShapeMatchingInstance(ShapeMatchingModelData model, in ShapeMatchingParameters parameters, float3 position,
            quaternion rotation, float3 velocity = default, bool perInstanceQuadratic = false)
        {
            Model = model;
            Parameters = parameters;
            int n = model.ParticleCount;
            Positions = new float3[n];
            Velocities = new float3[n];
            Clusters = new ClusterState[model.ClusterCount];
            QuadraticInverse = perInstanceQuadratic ? new float3x3[model.QuadraticInverse.Length] : Array.Empty<float3x3>();
            m_Predicted = new float3[n];
            m_Goals = new float3[n];
            m_Normals = new float3[n];
            Reset(position, rotation, velocity);
        }

        /// <summary>Back to the rest shape at a placement, moving uniformly (clusters and sleep state reset too).</summary>
        public void Reset(float3 position, quaternion rotation, float3 velocity = default) =>
            ShapeMatchingSolver.Initialize(Model.AsModel(), State, position, rotation, velocity, out Status);

        public ShapeMatchingState State =>
            new ShapeMatchingState(Positions, Velocities, Clusters, QuadraticInverse, m_Predicted, m_Goals, m_Normals);

        public ShapeMatchingStepReport Step(float dt, ReadOnlySpan<ColliderShape> colliders = default) =>
            ShapeMatchingSolver.Step(Model.AsModel(), Parameters, colliders, dt, State, ref Status);
    }
}
