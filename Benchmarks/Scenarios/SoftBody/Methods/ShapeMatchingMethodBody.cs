using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Shape matching in the method study: the mesh nodes are the particles, grouped into overlapping lattice clusters of
    /// <see cref="ClusterCells"/> cells (<see cref="ClusterBuilder"/>); frequency from <see cref="ShapeMatchingCalibration"/>
    /// (or given), ζ from the material; exactly the knob's substeps per step (the phase limit is lifted: shape matching's
    /// substep is stable at any h, so substeps buy accuracy only); no sleeping.
    /// </summary>
    public sealed class ShapeMatchingMethodBody : IMethodBody
    {
        /// <summary>Cluster size in cells of the box (the lattice spacing of cluster centres is half of it).</summary>
        public const float ClusterCells = 2f;

        readonly ShapeMatchingModelData m_Model;
        readonly ShapeMatchingParameters m_Parameters;
        readonly ClusterState[] m_Clusters;
        readonly float3[] m_Predicted, m_Goals, m_Normals;
        ParticleBodyStatus m_Status;

        public string Family { get; }
        public string Knob => $"{m_Parameters.Body.Substeps} substeps";
        public int ParticleCount => m_Model.ParticleCount;
        public float3[] RestPositions => m_Model.RestPositions;
        public float[] Masses => m_Model.Masses;
        public float3[] Positions { get; }
        public float3[] Velocities { get; }
        public int Resets => m_Status.ResetCount;
        /// <summary>The parameters in use (frequency, β, substeps).</summary>
        public ShapeMatchingParameters Parameters => m_Parameters;

        /// <param name="frequency">f (Hz); NaN = from <see cref="ShapeMatchingCalibration"/>.</param>
        /// <param name="plasticity">Plastic flow of the rest shape; none by default.</param>
        public ShapeMatchingMethodBody(MethodBodySetup setup, ShapeMatchingMode mode, int substeps, float cellSize, float frequency = float.NaN,
            PlasticityParameters plasticity = default)
        {
            float[] masses = setup.LumpedMasses();
            ClusterSet clusters = ClusterBuilder.Build(setup.Mesh.Positions, ClusterCells * cellSize * 1.001f);
            m_Model = ShapeMatchingModelData.Create(setup.Mesh.Positions, masses, clusters.Offsets, clusters.Particles,
                mode == ShapeMatchingMode.Quadratic, setup.Pinned);
            ShapeMatchingParameters p = ShapeMatchingCalibration.For(setup.Material, setup.CalibrationLength, setup.CalibrationLoad, mode, ShapeMatchingParameters.Default);
            if (!float.IsNaN(frequency))
                p.Frequency = frequency;
            p.Body.Substeps = substeps;
            p.MaxSubstepPhase = 1e6f;
            p.Body.SleepSpeed = 0f;
            p.Body.ParticleRadius = setup.ParticleRadius;
            p.Body.Friction = setup.Friction;
            p.Body.Restitution = 0f;
            p.Plasticity = plasticity;
            m_Parameters = p;
            Family = $"SM {mode.ToString().ToLowerInvariant()}";
            int n = m_Model.ParticleCount;
            Positions = new float3[n];
            Velocities = new float3[n];
            m_Clusters = new ClusterState[m_Model.ClusterCount];
            m_Predicted = new float3[n];
            m_Goals = new float3[n];
            m_Normals = new float3[n];
            Place();
        }

        ShapeMatchingState State => new ShapeMatchingState(Positions, Velocities, m_Clusters, Array.Empty<float3x3>(), m_Predicted, m_Goals, m_Normals);

        public void Place() =>
            ShapeMatchingSolver.Initialize(m_Model.AsModel(), State, m_Model.BodyRest.RestCenter, quaternion.identity, float3.zero, out m_Status);

        public void Step(float dt, float3 gravity, ReadOnlySpan<ColliderShape> colliders)
        {
            ShapeMatchingParameters p = m_Parameters;
            p.Body.Acceleration = gravity;
            ShapeMatchingSolver.Step(m_Model.AsModel(), p, colliders, dt, State, ref m_Status);
        }

        public void StateWritten() => ShapeMatchingSolver.Wake(ref m_Status);
    }
}
