using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>FEM in the method study: linear tetrahedra of the box, one material model and integrator, the knob's substeps per step; no sleeping.</summary>
    public sealed class FemMethodBody : IMethodBody
    {
        readonly FemModelData m_Model;
        readonly FemParameters m_Parameters;
        readonly quaternion[] m_Rotations;
        readonly float3[] m_ParticleScratch, m_ElementScratch;
        SoftBodyStatus m_Status;

        public string Family { get; }
        public string Knob => $"{m_Parameters.Substeps} substeps";
        public int ParticleCount => m_Model.RestPositions.Length;
        public float3[] RestPositions => m_Model.RestPositions;
        public float[] Masses => m_Model.Masses;
        public float3[] Positions { get; }
        public float3[] Velocities { get; }
        public int Resets => m_Status.ResetCount;

        /// <summary>A body of the setup; <paramref name="cgIterations"/>, <paramref name="cgTolerance"/> and <paramref name="iterations"/> replace the defaults (conjugate-gradient cap and relative residual of implicit Euler, XPBD iterations per substep) when positive.</summary>
        public FemMethodBody(MethodBodySetup setup, FemMaterialModel model, FemIntegrator integrator, int substeps,
            int cgIterations = 0, float cgTolerance = 0f, int iterations = 0)
        {
            var issues = new List<SoftBodyIssue>();
            m_Model = FemModelData.Create(setup.Mesh, setup.Material, setup.Pinned ?? new bool[setup.Mesh.NodeCount], issues)
                      ?? throw new InvalidOperationException("FEM bake failed: " + (issues.Count > 0 ? issues[0].Message : "?"));
            FemParameters p = FemParameters.Default;
            p.Model = model;
            p.Integrator = integrator;
            p.Substeps = substeps;
            if (cgIterations > 0)
                p.CgIterations = cgIterations;
            if (cgTolerance > 0f)
                p.CgTolerance = cgTolerance;
            if (iterations > 0)
                p.Iterations = iterations;
            p.SleepSpeed = 0f;
            p.ParticleRadius = setup.ParticleRadius;
            p.Friction = setup.Friction;
            p.Restitution = 0f;
            m_Parameters = p;
            Family = $"FEM {(model == FemMaterialModel.CoRotational ? "co-rotational" : "Neo-Hookean")} {Name(integrator)}";
            int n = m_Model.RestPositions.Length, e = setup.Mesh.TetrahedronCount;
            Positions = new float3[n];
            Velocities = new float3[n];
            m_Rotations = new quaternion[e];
            m_ParticleScratch = new float3[FemState.ScratchPerParticle * n];
            m_ElementScratch = new float3[FemState.ScratchPerElement * e];
            Place();
        }

        static string Name(FemIntegrator i) => i switch
        {
            FemIntegrator.SymplecticEuler => "explicit",
            FemIntegrator.ImplicitEuler => "implicit",
            _ => "XPBD",
        };

        FemState State => FemState.FromScratch(Positions, Velocities, m_Rotations, m_ParticleScratch, m_ElementScratch);

        public void Place() => FemSolver.Initialize(m_Model.AsModel(), State, m_Model.RestCenter, quaternion.identity, float3.zero, out m_Status);

        public void Step(float dt, float3 gravity, ReadOnlySpan<ColliderShape> colliders)
        {
            FemParameters p = m_Parameters;
            p.Acceleration = gravity;
            FemSolver.Step(m_Model.AsModel(), p, colliders, dt, State, ref m_Status);
        }

        public void StateWritten() => FemSolver.Wake(ref m_Status);
    }
}
