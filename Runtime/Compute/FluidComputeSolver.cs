using System;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Mathematics;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Compute
{
    /// <summary>
    /// A fluid on the GPU: FluidSolver.compute driven through <see cref="FluidComputeStep"/> (the recorder the lavapipe
    /// tests run). Every <see cref="FluidComputeBuffer"/> is a <see cref="GraphicsBuffer"/> created once, grown by doubling
    /// (the live particles move into the grown buffers on the GPU: a buffer copy would need equal sizes) and bound to every
    /// kernel by a cached property ID; group counts come from each kernel's reflected
    /// size; particle kernels are dispatched indirectly, since only the GPU knows the live count. The particle state stays
    /// on the GPU. The step's counters, the live count and the fastest speed come back through an asynchronous read-back,
    /// so the substeps of a step follow the speed read back from an earlier one (never a stall).
    /// </summary>
    public sealed class FluidComputeSolver : IFluidComputeCommands, IDisposable
    {
        readonly ComputeKernelSet m_Kernels;
        readonly ComputeConstantBuffer<FluidComputeConstants> m_ConstantBuffer;
        readonly GraphicsBuffer[] m_Buffers = new GraphicsBuffer[Enum.GetValues(typeof(FluidComputeBuffer)).Length];
        readonly uint[] m_Stats = new uint[FluidComputeLayout.StatCount];
        FluidConstants m_Constants;
        int m_Capacity, m_Colliders, m_Drains;
        readonly GpuReadback<uint> m_Readback = new GpuReadback<uint>();
        float m_LastMaxSpeed;
        /// <summary>Position-based: the depth of the last read-back (m), for the depth rule of the substeps.</summary>
        float m_LastDepth;

        /// <summary>A solver for the fluid <paramref name="constants"/> with room for <paramref name="capacity"/> particles.</summary>
        public FluidComputeSolver(ComputeShader shader, in FluidConstants constants, int capacity)
        {
            m_Kernels = new ComputeKernelSet(shader, typeof(FluidKernel), typeof(FluidComputeBuffer), typeof(FluidComputeGlobal));
            m_ConstantBuffer = new ComputeConstantBuffer<FluidComputeConstants>(shader, FluidComputeConstants.BufferName, FluidComputeConstants.Bytes);
            m_Constants = constants;
            Allocate(math.max(capacity, 1));
        }

        /// <summary>Particle slots on the GPU.</summary>
        public int Capacity => m_Capacity;
        /// <summary>Live particles at the last completed read-back.</summary>
        public int LastKnownCount => (int)m_Stats[FluidComputeLayout.StatLive];
        /// <summary>The counters of the last step whose read-back completed.</summary>
        public ReadOnlySpan<uint> LastStats => m_Stats;
        /// <summary>A buffer, for the renderer (positions) or a read-back (<see cref="FluidComputeBuffer.Positions"/>: xyz, age in w).</summary>
        public GraphicsBuffer Buffer(FluidComputeBuffer buffer) => m_Buffers[(int)buffer];

        void Allocate(int capacity)
        {
            int cells = m_Constants.Grid.CellCount;
            var kept = new GraphicsBuffer[m_Buffers.Length];
            bool copy = false;
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                var id = (FluidComputeBuffer)b;
                int length = FluidComputeLayout.Length(id, capacity, cells, m_Colliders + m_Drains);
                GraphicsBuffer old = m_Buffers[b];
                if (old != null && old.count >= length)
                    continue;
                var target = id == FluidComputeBuffer.Args ? GraphicsBuffer.Target.Structured | GraphicsBuffer.Target.IndirectArguments : GraphicsBuffer.Target.Structured;
                m_Buffers[b] = new GraphicsBuffer(target, length, FluidComputeLayout.Stride(id));
                if (old != null && FluidComputeLayout.HoldsState(id))
                {
                    kept[b] = old;
                    copy = true;
                }
                else
                    old?.Release();
            }
            m_Capacity = capacity;
            BindBuffers();
            if (!copy)
                return;
            // The live particles into the grown buffers: PermuteCopyBack with the old buffers bound as its Out partners.
            int kernel = (int)FluidKernel.PermuteCopyBack;
            for (int b = 0; b < kept.Length; b++)
                if (kept[b] != null)
                    m_Kernels.Bind(kernel, (int)FluidComputeLayout.OutPartner((FluidComputeBuffer)b), kept[b]);
            m_Kernels.DispatchIndirect(kernel, m_Buffers[(int)FluidComputeBuffer.Args]);
            for (int b = 0; b < kept.Length; b++)
                if (kept[b] != null)
                {
                    int partner = (int)FluidComputeLayout.OutPartner((FluidComputeBuffer)b);
                    m_Kernels.Bind(kernel, partner, m_Buffers[partner]);
                    kept[b].Release();
                }
        }

        /// <summary>Uploads the colliders (world space) and drains of the following steps.</summary>
        public void SetShapes(NativeArray<ColliderShape> colliders, NativeArray<FluidDrain> drains)
        {
            m_Colliders = colliders.Length;
            m_Drains = drains.Length;
            Allocate(m_Capacity);
            var packed = new NativeArray<float4>(FluidComputeLayout.ShapeFloat4s * math.max(m_Colliders + m_Drains, 1), Allocator.Temp);
            int n = FluidComputeStep.PackShapes(colliders.AsReadOnlySpan(), drains.AsReadOnlySpan(), packed.AsSpan());
            m_Buffers[(int)FluidComputeBuffer.Shapes].SetData(packed, 0, 0, math.max(n, 1));
        }

        /// <summary>Marks the particles inside a drain (<see cref="FluidDrain.Apply"/>); the next step's sort removes them.</summary>
        public void Drain()
        {
            var self = this;
            FluidComputeStep.RecordDrain(ref self, ConstantsOf(0f, 0f));
        }

        FluidComputeConstants ConstantsOf(float h, float dt) => FluidComputeConstants.Of(m_Constants, h, dt, m_Colliders, m_Drains);

        /// <summary>
        /// Writes <see cref="FluidComputeBuffer.RenderParticles"/> (position and attribute of every live particle, NaN in
        /// the other slots) for the fluid renderer; <see cref="Capacity"/> slots in all.
        /// </summary>
        public void PackRender()
        {
            var self = this;
            FluidComputeStep.RecordPackRender(ref self, m_Capacity);
        }

        /// <summary>Grows every buffer to at least <paramref name="capacity"/> particles by doubling, keeping the state.</summary>
        public void EnsureCapacity(int capacity)
        {
            if (capacity <= m_Capacity)
                return;
            Allocate(FluidComputeLayout.GrownCapacity(m_Capacity, capacity));
        }

        /// <summary>
        /// Replaces the particles with <paramref name="count"/> packed ones (<see cref="FluidComputeStep.Pack"/>: position
        /// with age, velocity with lifetime, extras), growing the buffers when needed.
        /// </summary>
        public void Upload(NativeArray<float4> positions, NativeArray<float4> velocities, NativeArray<FluidComputeExtras> extras, int count)
        {
            EnsureCapacity(count);
            m_Buffers[(int)FluidComputeBuffer.Positions].SetData(positions, 0, 0, count);
            m_Buffers[(int)FluidComputeBuffer.Velocities].SetData(velocities, 0, 0, count);
            m_Buffers[(int)FluidComputeBuffer.Extras].SetData(extras, 0, 0, count);
            var stats = new NativeArray<uint>(FluidComputeLayout.StatCount, Allocator.Temp);
            stats[FluidComputeLayout.StatLive] = (uint)count;
            m_Buffers[(int)FluidComputeBuffer.Stats].SetData(stats, 0, 0, stats.Length);
            var args = new NativeArray<uint>(3, Allocator.Temp);
            args[0] = (uint)((count + FluidComputeLayout.ThreadGroupSize - 1) / FluidComputeLayout.ThreadGroupSize);
            args[1] = 1;
            args[2] = 1;
            m_Buffers[(int)FluidComputeBuffer.Args].SetData(args, 0, 0, 3);
            m_Stats[FluidComputeLayout.StatLive] = (uint)count;
        }

        /// <summary>
        /// Appends <paramref name="count"/> packed particles (a tap's spawns) after the live ones, up to the capacity; the
        /// caller grows the capacity first when its own count says so.
        /// </summary>
        public void Emit(NativeArray<float4> positions, NativeArray<float4> velocities, NativeArray<FluidComputeExtras> extras, int count)
        {
            if (count <= 0)
                return;
            EnsureCapacity(count);
            m_Buffers[(int)FluidComputeBuffer.PositionsOut].SetData(positions, 0, 0, count);
            m_Buffers[(int)FluidComputeBuffer.VelocitiesOut].SetData(velocities, 0, 0, count);
            m_Buffers[(int)FluidComputeBuffer.ExtrasOut].SetData(extras, 0, 0, count);
            var self = this;
            FluidComputeStep.RecordEmit(ref self, count, m_Capacity);
        }

        /// <summary>
        /// Dispatches one step of <paramref name="dt"/> seconds; its substeps follow the fastest speed of the last completed
        /// read-back. Returns the substeps dispatched.
        /// </summary>
        public int Step(float dt)
        {
            if (!(dt > 0f) || !math.isfinite(dt))
                return 0;
            var self = this;
            FluidSolver.Plan plan = FluidSolver.PlanOf(dt,
                FluidSolver.Substeps(m_Constants, math.min(m_LastMaxSpeed, m_Constants.Parameters.MaxSpeed), m_LastDepth, dt));
            FluidComputeStep.RecordBegin(ref self, ConstantsOf(0f, plan.SimulatedTime));
            Span<FluidPass> passes = stackalloc FluidPass[FluidSubstepPasses.MaxPasses];
            int passCount = FluidSubstepPasses.Write(m_Constants, plan.H, m_Colliders > 0, passes);
            FluidComputeStep.RecordSubsteps(ref self, m_Constants, ConstantsOf(plan.H, plan.SimulatedTime), plan.Substeps,
                passes.Slice(0, passCount));
            RequestStats();
            return plan.Substeps;
        }

        /// <summary>
        /// Takes the counters of a completed read-back (never waited for; <see cref="GpuReadback{T}"/> keeps them until taken,
        /// whichever frame they arrived in) and asks for the next one when none is in flight.
        /// </summary>
        void RequestStats()
        {
            ReadOnlySpan<uint> data = m_Readback.Take();
            if (data.Length > 0)
            {
                for (int i = 0; i < m_Stats.Length && i < data.Length; i++)
                    m_Stats[i] = data[i];
                m_LastMaxSpeed = math.sqrt(math.asfloat(m_Stats[FluidComputeLayout.StatMaxSpeedSquared]));
                m_LastDepth = FluidComputeLayout.DepthOf(m_Constants, m_Stats);
            }
            m_Readback.Request(m_Buffers[(int)FluidComputeBuffer.Stats]);
        }

        public void SetConstants(in FluidComputeConstants constants) => m_ConstantBuffer.Set(constants);
        public void SetInts(FluidComputeGlobal name, int4 value) => m_Kernels.SetInts((int)name, value);
        public void BindBuffers()
        {
            for (int b = 0; b < m_Buffers.Length; b++)
                m_Kernels.Bind(b, m_Buffers[b]);
        }

        public void Dispatch(FluidKernel kernel, int threads) => m_Kernels.Dispatch((int)kernel, threads);
        public void DispatchIndirect(FluidKernel kernel) => m_Kernels.DispatchIndirect((int)kernel, m_Buffers[(int)FluidComputeBuffer.Args]);

        /// <summary>Releases every buffer.</summary>
        public void Dispose()
        {
            m_Readback.Dispose();
            m_ConstantBuffer.Dispose();
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                m_Buffers[b]?.Release();
                m_Buffers[b] = null;
            }
        }
    }
}
