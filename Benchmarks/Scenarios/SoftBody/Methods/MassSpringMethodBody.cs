using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Mass-spring in the method study: springs along the tetrahedra's edges (<see cref="MassSpringNetwork"/>), stiffness
    /// from <see cref="MassSpringCalibration"/>, one integrator, the knob's substeps per step; no sleeping.
    /// </summary>
    public sealed class MassSpringMethodBody : IMethodBody
    {
        readonly MassSpringModelData m_Model;
        readonly MassSpringParameters m_Parameters;
        readonly float3[] m_Scratch, m_SpringScratch;
        ParticleBodyStatus m_Status;

        public string Family { get; }
        public string Knob => $"{m_Parameters.Body.Substeps} substeps";
        public int ParticleCount => m_Model.RestPositions.Length;
        public float3[] RestPositions => m_Model.RestPositions;
        public float[] Masses => m_Model.Masses;
        public float3[] Positions { get; }
        public float3[] Velocities { get; }
        public int Resets => m_Status.ResetCount;
        /// <summary>Residual of the calibration fit (<see cref="MassSpringCalibration.Result.Residual"/>).</summary>
        public double CalibrationResidual { get; }

        /// <param name="cgIterations">Implicit Euler: cap on CG iterations per substep; 0 = the solver's default.</param>
        public MassSpringMethodBody(MethodBodySetup setup, MassSpringIntegrator integrator, int substeps, int cgIterations = 0)
        {
            var issues = new List<ValidationIssue>();
            m_Model = MassSpringModelData.FromMesh(setup.Mesh, setup.Material, MassSpringBuildSettings.Default, issues,
                out MassSpringCalibration.Result calibration, setup.Pinned)
                ?? throw new InvalidOperationException("Mass-spring bake failed: " + (issues.Count > 0 ? issues[0].Message : "?"));
            CalibrationResidual = calibration.Residual;
            MassSpringParameters p = MassSpringParameters.Default;
            p.Integrator = integrator;
            p.Body.Substeps = substeps;
            if (cgIterations > 0)
                p.CgIterations = cgIterations;
            p.Body.SleepSpeed = 0f;
            p.Body.ParticleRadius = setup.ParticleRadius;
            p.Body.Friction = setup.Friction;
            p.Body.Restitution = 0f;
            m_Parameters = p;
            Family = "MS " + Name(integrator);
            int n = m_Model.RestPositions.Length;
            Positions = new float3[n];
            Velocities = new float3[n];
            m_Scratch = new float3[MassSpringState.ScratchPerParticle * n];
            m_SpringScratch = new float3[MassSpringState.ScratchPerSpring * m_Model.Springs.Length];
            Place();
        }

        static string Name(MassSpringIntegrator i) => i switch
        {
            MassSpringIntegrator.SymplecticEuler => "symplectic Euler",
            MassSpringIntegrator.Verlet => "Verlet",
            MassSpringIntegrator.ImplicitEuler => "implicit Euler",
            _ => "XPBD",
        };

        MassSpringState State => new MassSpringState(Positions, Velocities, m_Scratch, m_SpringScratch);

        public void Place() => MassSpringSolver.Initialize(m_Model.AsModel(), State, m_Model.RestCenter, quaternion.identity, float3.zero, out m_Status);

        public void Step(float dt, float3 gravity, ReadOnlySpan<ColliderShape> colliders)
        {
            MassSpringParameters p = m_Parameters;
            p.Body.Acceleration = gravity;
            MassSpringSolver.Step(m_Model.AsModel(), p, colliders, dt, State, ref m_Status);
        }

        public void StateWritten() => MassSpringSolver.Wake(ref m_Status);
    }
}
