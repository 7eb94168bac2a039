using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// FEM in the method study: linear or quadratic tetrahedra of the box, one material model and integrator, the knob's
    /// substeps per step, implicit solves preconditioned by block-Jacobi or the rest factor (<see cref="FemRestFactor"/>,
    /// with warm starts); no sleeping.
    /// </summary>
    public sealed class FemMethodBody : IMethodBody, IIterativeMethodBody
    {
        readonly FemModelData m_Model;
        readonly FemParameters m_Parameters;
        readonly quaternion[] m_Rotations;
        readonly float3[] m_ParticleScratch, m_ElementScratch, m_WarmStart;
        ParticleBodyStatus m_Status;
        long m_CgIterations, m_Substeps;
        float m_CgResidual;

        public string Family { get; }
        public string Knob => $"{m_Parameters.Body.Substeps} substeps";
        public int ParticleCount => m_Model.RestPositions.Length;
        public float3[] RestPositions => m_Model.RestPositions;
        public float[] Masses => m_Model.Masses;
        public float3[] Positions { get; }
        public float3[] Velocities { get; }
        public int Resets => m_Status.ResetCount;
        public long CgIterations => m_CgIterations;
        public long ImplicitSubsteps => m_Substeps;
        public double MaxCgResidual => m_CgResidual;

        /// <summary>A body of the setup; <paramref name="cgIterations"/>, <paramref name="cgTolerance"/> and <paramref name="iterations"/> replace the defaults (conjugate-gradient cap and relative residual of implicit Euler, XPBD iterations per substep) when positive.</summary>
        public FemMethodBody(MethodBodySetup setup, FemMaterialModel model, FemIntegrator integrator, int substeps,
            int cgIterations = 0, float cgTolerance = 0f, int iterations = 0, FemElementOrder order = FemElementOrder.Linear,
            bool restFactor = false)
        {
            var issues = new List<ValidationIssue>();
            m_Model = FemModelData.Create(setup.Mesh, setup.Material, setup.Pinned ?? new bool[setup.Mesh.NodeCount], issues, order)
                      ?? throw new InvalidOperationException("FEM bake failed: " + (issues.Count > 0 ? issues[0].Message : "?"));
            FemParameters p = FemParameters.Default;
            p.Model = model;
            p.Integrator = integrator;
            p.Body.Substeps = substeps;
            if (cgIterations > 0)
                p.CgIterations = cgIterations;
            if (cgTolerance > 0f)
                p.CgTolerance = cgTolerance;
            if (iterations > 0)
                p.Iterations = iterations;
            p.Body.SleepSpeed = 0f;
            p.DampingFrequency = setup.DampingFrequency;
            p.Body.ParticleRadius = setup.ParticleRadius;
            p.Body.Friction = setup.Friction;
            p.Body.Restitution = 0f;
            m_Parameters = p;
            // The rest factor is built for the scene's frame and this body's substeps and damping.
            if (restFactor && integrator == FemIntegrator.ImplicitEuler)
                m_Model.BuildRestFactor(StudyScene.Dt / substeps, FemSolver.DampingCoefficient(m_Model.AsModel(), p.Sanitized()));
            Family = FamilyName(model, integrator, order);
            int n = m_Model.RestPositions.Length, points = m_Model.AsModel().PointCount;
            Positions = new float3[n];
            Velocities = new float3[n];
            m_Rotations = new quaternion[points];
            m_ParticleScratch = new float3[FemState.ScratchPerParticle * n];
            m_ElementScratch = new float3[FemState.ScratchPerElement * points];
            m_WarmStart = new float3[n];
            Place();
        }

        /// <summary>"FEM co-rotational implicit", "FEM Neo-Hookean XPBD", …, with " quadratic" for 10-node elements.</summary>
        public static string FamilyName(FemMaterialModel model, FemIntegrator integrator, FemElementOrder order = FemElementOrder.Linear) =>
            $"FEM {(model == FemMaterialModel.CoRotational ? "co-rotational" : "Neo-Hookean")} {Name(integrator)}" +
            (order == FemElementOrder.Quadratic ? " quadratic" : "");

        static string Name(FemIntegrator i) => i switch
        {
            FemIntegrator.SymplecticEuler => "explicit",
            FemIntegrator.ImplicitEuler => "implicit",
            _ => "XPBD",
        };

        FemState State => FemState.FromScratch(Positions, Velocities, m_Rotations, m_ParticleScratch, m_ElementScratch, m_WarmStart);

        public void Place()
        {
            FemSolver.Initialize(m_Model.AsModel(), State, m_Model.RestCenter, quaternion.identity, float3.zero, out m_Status);
        }

        public void Step(float dt, float3 gravity, ReadOnlySpan<ColliderShape> colliders)
        {
            FemParameters p = m_Parameters;
            p.Body.Acceleration = gravity;
            FemStepReport report = FemSolver.Step(m_Model.AsModel(), p, colliders, dt, State, ref m_Status);
            if (report.Integrator == FemIntegrator.ImplicitEuler && report.Step.Substeps > 0)
            {
                m_CgIterations += report.TotalCgIterations;
                m_Substeps += report.Step.Substeps;
                m_CgResidual = Math.Max(m_CgResidual, report.MaxCgResidual);
            }
        }

        public void StateWritten() => FemSolver.Wake(ref m_Status);
    }
}
