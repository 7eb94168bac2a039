using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A scene as the package's fixed step runs it (<c>ParticleSimulationSystemGroup</c>), in .NET on one thread: each
    /// particle body's method step against the collider world, then the fluid's frame, through the solver functions the ECS
    /// systems call. What the scene does not contain runs no step: a frame of an empty scene is a loop over an empty list.
    /// <see cref="Start"/> runs the scene into its timed state and keeps it; every <see cref="Step"/> then puts the particles
    /// back there and runs one frame, so every timed frame is the same frame, with or without an effect.
    /// </summary>
    public sealed class EffectScene
    {
        /// <summary>Frame (s).</summary>
        public const float Frame = 1f / 60f;

        static readonly float3 s_Gravity = new float3(0f, -9.81f, 0f);

        /// <summary>The particle bodies, stepped in order.</summary>
        public readonly List<IMethodBody> Bodies = new List<IMethodBody>();
        /// <summary>The static colliders every body and the fluid see.</summary>
        public ColliderShape[] Colliders = Array.Empty<ColliderShape>();
        /// <summary>The fluid's particles, or null for a scene without fluid.</summary>
        public FluidBuffers Fluid;
        /// <summary>The fluid's constants (when <see cref="Fluid"/> is set).</summary>
        public FluidConstants FluidConstants;

        readonly List<float3[]> m_Saved = new List<float3[]>();
        float3[] m_FluidPositions, m_FluidVelocities;
        float[] m_FluidAges, m_FluidLifetimes, m_FluidAttributes;
        int[] m_FluidIds;
        FluidStatus m_FluidStatus;
        bool m_Started;

        /// <summary>Body steps run so far (one per body per frame).</summary>
        public int BodySteps { get; private set; }
        /// <summary>Fluid substeps run so far.</summary>
        public int FluidSubsteps { get; private set; }
        /// <summary>Body steps and fluid substeps of the last frame.</summary>
        public int LastBodySteps { get; private set; }
        public int LastFluidSubsteps { get; private set; }

        /// <summary>NaN-guard resets of the bodies and the fluid's invalid particles.</summary>
        public long Resets
        {
            get
            {
                long r = 0;
                foreach (IMethodBody b in Bodies)
                    r += b.Resets;
                return r + (Fluid != null ? Fluid.Status.Invalid : 0);
            }
        }

        /// <summary>Particles of every body and the fluid.</summary>
        public int ParticleCount
        {
            get
            {
                int n = Fluid != null ? Fluid.Status.Count : 0;
                foreach (IMethodBody b in Bodies)
                    n += b.ParticleCount;
                return n;
            }
        }

        /// <summary>Runs <paramref name="frames"/> frames from the initial state and keeps the result as the state every <see cref="Step"/> starts from.</summary>
        public void Start(int frames)
        {
            for (int f = 0; f < frames; f++)
                Advance();
            m_Saved.Clear();
            foreach (IMethodBody b in Bodies)
            {
                m_Saved.Add((float3[])b.Positions.Clone());
                m_Saved.Add((float3[])b.Velocities.Clone());
            }
            if (Fluid != null)
            {
                m_FluidPositions = (float3[])Fluid.Positions.Clone();
                m_FluidVelocities = (float3[])Fluid.Velocities.Clone();
                m_FluidAges = (float[])Fluid.Ages.Clone();
                m_FluidLifetimes = (float[])Fluid.Lifetimes.Clone();
                m_FluidAttributes = (float[])Fluid.Attributes.Clone();
                m_FluidIds = (int[])Fluid.Ids.Clone();
                m_FluidStatus = Fluid.Status;
            }
            m_Started = true;
        }

        /// <summary>One fixed step of <see cref="Frame"/> from the started state (see <see cref="Start"/>): the bodies in order, then the fluid.</summary>
        public void Step()
        {
            if (m_Started)
                Restore();
            Advance();
        }

        void Restore()
        {
            for (int i = 0; i < Bodies.Count; i++)
            {
                IMethodBody b = Bodies[i];
                Array.Copy(m_Saved[2 * i], b.Positions, b.ParticleCount);
                Array.Copy(m_Saved[2 * i + 1], b.Velocities, b.ParticleCount);
                b.StateWritten();
            }
            if (Fluid != null)
            {
                Array.Copy(m_FluidPositions, Fluid.Positions, m_FluidPositions.Length);
                Array.Copy(m_FluidVelocities, Fluid.Velocities, m_FluidVelocities.Length);
                Array.Copy(m_FluidAges, Fluid.Ages, m_FluidAges.Length);
                Array.Copy(m_FluidLifetimes, Fluid.Lifetimes, m_FluidLifetimes.Length);
                Array.Copy(m_FluidAttributes, Fluid.Attributes, m_FluidAttributes.Length);
                Array.Copy(m_FluidIds, Fluid.Ids, m_FluidIds.Length);
                Fluid.Status = m_FluidStatus;
            }
        }

        void Advance()
        {
            ReadOnlySpan<ColliderShape> colliders = Colliders;
            LastBodySteps = LastFluidSubsteps = 0;
            for (int i = 0; i < Bodies.Count; i++)
            {
                Bodies[i].Step(Frame, s_Gravity, colliders);
                LastBodySteps++;
            }
            if (Fluid != null)
                LastFluidSubsteps = FluidSolver.Step(FluidConstants, colliders, Frame, Fluid.Particles, Fluid.Scratch, ref Fluid.Status).Substeps;
            BodySteps += LastBodySteps;
            FluidSubsteps += LastFluidSubsteps;
        }
    }
}
