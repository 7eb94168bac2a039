using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The hybrid in the method study: linear shape matching and XPBD springs in one step (<see cref="HybridSolver"/>),
    /// each carrying half the material's stiffness (springs calibrated to E/2, shape-matching frequency the calibrated one
    /// over √2, since its stiffness goes as f²); the knob's substeps per step.
    /// </summary>
    public sealed class HybridMethodBody : IMethodBody
    {
        readonly ShapeMatchingModelData m_Shape;
        readonly MassSpringModelData m_Springs;
        readonly ShapeMatchingParameters m_ShapeParameters;
        readonly MassSpringParameters m_SpringParameters;
        readonly ClusterState[] m_Clusters;
        readonly float3[] m_Predicted, m_Goals, m_Normals, m_Scratch, m_SpringScratch;
        ParticleBodyStatus m_Status;

        public string Family => "Hybrid SM + MS XPBD";
        public string Knob => $"{m_ShapeParameters.Body.Substeps} substeps";
        public int ParticleCount => m_Shape.ParticleCount;
        public float3[] RestPositions => m_Shape.RestPositions;
        public float[] Masses => m_Shape.Masses;
        public float3[] Positions { get; }
        public float3[] Velocities { get; }
        public int Resets => m_Status.ResetCount;

        public HybridMethodBody(MethodBodySetup setup, int substeps, float cellSize)
        {
            ElasticMaterial half = setup.Material;
            half.YoungsModulus *= 0.5f;
            var issues = new List<ValidationIssue>();
            m_Springs = MassSpringModelData.FromMesh(setup.Mesh, half, MassSpringBuildSettings.Default, issues, out _, setup.Pinned)
                        ?? throw new InvalidOperationException("Mass-spring bake failed");
            ClusterSet clusters = ClusterBuilder.Build(setup.Mesh.Positions, ShapeMatchingMethodBody.ClusterCells * cellSize * 1.001f);
            m_Shape = ShapeMatchingModelData.Create(setup.Mesh.Positions, m_Springs.Masses, clusters.Offsets, clusters.Particles, false, setup.Pinned);
            ShapeMatchingParameters sp = ShapeMatchingCalibration.For(half, setup.CalibrationLength, setup.CalibrationLoad, ShapeMatchingMode.Linear, ShapeMatchingParameters.Default);
            sp.Body.Substeps = substeps;
            sp.MaxSubstepPhase = 1e6f;
            sp.Body.SleepSpeed = 0f;
            sp.Body.ParticleRadius = setup.ParticleRadius;
            sp.Body.Friction = setup.Friction;
            sp.Body.Restitution = 0f;
            m_ShapeParameters = sp;
            MassSpringParameters mp = MassSpringParameters.Default;
            mp.Integrator = MassSpringIntegrator.Xpbd;
            mp.Body.Substeps = substeps;
            mp.Body.SleepSpeed = 0f;
            m_SpringParameters = mp;
            int n = m_Shape.ParticleCount;
            Positions = new float3[n];
            Velocities = new float3[n];
            m_Clusters = new ClusterState[m_Shape.ClusterCount];
            m_Predicted = new float3[n];
            m_Goals = new float3[n];
            m_Normals = new float3[n];
            m_Scratch = new float3[MassSpringState.ScratchPerParticle * n];
            m_SpringScratch = new float3[MassSpringState.ScratchPerSpring * m_Springs.Springs.Length];
            Place();
        }

        ShapeMatchingState ShapeState => new ShapeMatchingState(Positions, Velocities, m_Clusters, Array.Empty<float3x3>(), m_Predicted, m_Goals, m_Normals);

        public void Place() =>
            ShapeMatchingSolver.Initialize(m_Shape.AsModel(), ShapeState, m_Shape.BodyRest.RestCenter, quaternion.identity, float3.zero, out m_Status);

        public void Step(float dt, float3 gravity, ReadOnlySpan<ColliderShape> colliders)
        {
            ShapeMatchingParameters sp = m_ShapeParameters;
            sp.Body.Acceleration = gravity;
            MassSpringParameters mp = m_SpringParameters;
            mp.Body.Acceleration = gravity;
            HybridSolver.Step(m_Shape.AsModel(), sp, ShapeState, m_Springs.AsModel(), mp,
                new MassSpringState(Positions, Velocities, m_Scratch, m_SpringScratch), colliders, dt, ref m_Status);
        }

        public void StateWritten() => ShapeMatchingSolver.Wake(ref m_Status);
    }
}
