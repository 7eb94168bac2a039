using System;
using Unity.Mathematics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Small mass-spring bodies and a runner shared by the mass-spring tests.</summary>
    sealed class MassSpringTestBody
    {
        public MassSpringModelData Data;
        public float3[] Positions, Velocities, Scratch, SpringScratch;
        public ParticleBodyStatus Status;

        public MassSpringTestBody(MassSpringModelData data)
        {
            Data = data;
            int n = data.ParticleCount;
            Positions = (float3[])data.RestPositions.Clone();
            Velocities = new float3[n];
            Scratch = new float3[MassSpringState.ScratchPerParticle * n];
            SpringScratch = new float3[MassSpringState.ScratchPerSpring * data.SpringCount];
            Status = new ParticleBodyStatus { Rotation = quaternion.identity };
        }

        public MassSpringState State => MassSpringState.FromScratch(Positions, Velocities, Scratch, SpringScratch);

        public ParticleStepReport Step(in MassSpringParameters p, float dt, int batch = 0) =>
            MassSpringSolver.Step(Data.AsModel(), p, ReadOnlySpan<ColliderShape>.Empty, dt, State, ref Status, batch);

        /// <summary>
        /// A chain along x of <paramref name="springs"/> springs of rest length <paramref name="restLength"/> (m), stiffness
        /// <paramref name="k"/> and dashpot <paramref name="damping"/> between particles of mass <paramref name="m"/>, particle
        /// 0 at x = <paramref name="start"/> (pinned when <paramref name="fixedFirst"/>), particle i at start + i · restLength.
        /// </summary>
        public static MassSpringTestBody Chain(int springs, float k, float m, bool fixedFirst, float damping = 0f, float restLength = 1f,
            float start = -1f)
        {
            var rest = new float3[springs + 1];
            var masses = new float[springs + 1];
            var pinned = new bool[springs + 1];
            var list = new Spring[springs];
            for (int i = 0; i <= springs; i++)
            {
                rest[i] = new float3(start + i * restLength, 0f, 0f);
                masses[i] = m;
            }
            for (int e = 0; e < springs; e++)
                list[e] = new Spring(e, e + 1, restLength, k, damping);
            pinned[0] = fixedFirst;
            return new MassSpringTestBody(MassSpringModelData.Create(rest, masses, list, pinned));
        }

        /// <summary>Parameters for oracle tests: one substep per step, no gravity, no sleep, a generous guard.</summary>
        public static MassSpringParameters Plain(MassSpringIntegrator integrator, float maxSpeed = 1e6f)
        {
            MassSpringParameters p = MassSpringParameters.Default;
            p.Integrator = integrator;
            p.Body.Substeps = 1;
            p.Body.Acceleration = float3.zero;
            p.Body.SleepSpeed = 0f;
            p.Body.ParticleRadius = 0f;
            p.Body.MaxSpeed = maxSpeed;
            p.CgIterations = 100;
            p.CgTolerance = 1e-6f;
            return p;
        }

        /// <summary>A calibrated box of tetrahedra (cells of <paramref name="cell"/> m) with <paramref name="material"/>.</summary>
        public static MassSpringModelData Box(int nx, int ny, int nz, float cell, ElasticMaterial material, bool bending = false,
            bool[] pinned = null)
        {
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(nx, ny, nz) * cell, new int3(nx, ny, nz), 0.5f * cell * new float3(nx, ny, nz));
            var issues = new System.Collections.Generic.List<ValidationIssue>();
            return MassSpringModelData.FromMesh(mesh, material, new MassSpringBuildSettings { BendingSprings = bending }, issues, out _, pinned);
        }
    }
}
