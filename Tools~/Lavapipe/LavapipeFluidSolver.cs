using System;
using System.Collections.Generic;
using System.IO;
using Unity.Mathematics;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Lavapipe
{
    /// <summary>
    /// The GPU fluid step (Shaders/FluidSolver.compute, recorded by <see cref="FluidComputeStep"/>) on lavapipe:
    /// the harness counterpart of Unity's FluidComputeSolver. Buffers are created once, grown by doubling, and bound to
    /// every kernel by name. The fastest speed is read back after the step's first dispatches to choose the substeps (the
    /// CPU path's rule); Unity reads it back asynchronously instead.
    /// </summary>
    public sealed class LavapipeFluidSolver : IFluidComputeCommands, IDisposable
    {
        readonly LavapipeDevice m_Device;
        readonly LavapipeComputeShader m_Shader;
        readonly int[] m_Kernels;
        readonly string[] m_GlobalNames;
        readonly LavapipeBuffer[] m_Buffers = new LavapipeBuffer[Enum.GetValues(typeof(FluidComputeBuffer)).Length];
        FluidConstants m_Constants;
        int m_Capacity, m_Cells, m_Colliders, m_Drains;

        /// <summary>When set, every dispatch is submitted alone and its time added to <see cref="KernelMilliseconds"/>.</summary>
        public bool TimeKernels;
        public readonly Dictionary<FluidKernel, (double Milliseconds, int Dispatches)> KernelMilliseconds = new Dictionary<FluidKernel, (double, int)>();

        /// <summary>The package's FluidSolver.compute, found from this assembly's folder upward.</summary>
        public static string ComputePath()
        {
            string dir = AppContext.BaseDirectory;
            while (dir != null)
            {
                string candidate = Path.Combine(dir, "Shaders", "FluidSolver.compute");
                if (File.Exists(candidate) && File.Exists(Path.Combine(dir, "package.json")))
                    return candidate;
                dir = Path.GetDirectoryName(dir);
            }
            throw new FileNotFoundException("Shaders/FluidSolver.compute not found above " + AppContext.BaseDirectory);
        }

        public LavapipeFluidSolver(LavapipeDevice device, LavapipeComputeShader shader, in FluidConstants constants, int capacity)
        {
            m_Device = device;
            m_Shader = shader;
            var names = Enum.GetNames(typeof(FluidKernel));
            m_Kernels = new int[names.Length];
            for (int k = 0; k < names.Length; k++)
                m_Kernels[k] = shader.FindKernel(names[k]);
            m_GlobalNames = Array.ConvertAll(Enum.GetNames(typeof(FluidComputeGlobal)), n => "_" + n);
            m_Constants = constants;
            Allocate(math.max(capacity, 1), constants.Grid.CellCount);
        }

        public int Capacity => m_Capacity;
        public LavapipeBuffer Buffer(FluidComputeBuffer b) => m_Buffers[(int)b];
        public Span<uint> Stats => Buffer(FluidComputeBuffer.Stats).As<uint>();
        public int Count => (int)Stats[FluidComputeLayout.StatLive];

        /// <summary>
        /// Creates or grows the buffers and binds them (and <see cref="BindBuffers"/> again at each recording); the live particles move into grown state buffers on the GPU, the
        /// way FluidComputeSolver does it (PermuteCopyBack with the old buffers bound as its Out partners).
        /// </summary>
        void Allocate(int capacity, int cells)
        {
            var kept = new LavapipeBuffer[m_Buffers.Length];
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                var id = (FluidComputeBuffer)b;
                long bytes = (long)FluidComputeLayout.Length(id, capacity, cells, m_Colliders + m_Drains) * FluidComputeLayout.Stride(id);
                LavapipeBuffer old = m_Buffers[b];
                if (old != null && old.Bytes >= bytes)
                    continue;
                var created = m_Device.CreateBuffer(bytes);
                if (old != null && FluidComputeLayout.HoldsState(id))
                    kept[b] = old;
                else if (old != null)
                {
                    // Fixed-size buffers (counters, arguments, the cell table) never grow; scratch is rewritten each substep.
                    old.As<byte>().Slice(0, (int)Math.Min(old.Bytes, created.Bytes)).CopyTo(created.As<byte>());
                    old.Dispose();
                }
                m_Buffers[b] = created;
            }
            m_Capacity = capacity;
            m_Cells = cells;
            int copyBack = m_Kernels[(int)FluidKernel.PermuteCopyBack];
            BindBuffers();
            if (Array.TrueForAll(kept, k => k == null))
                return;
            for (int b = 0; b < kept.Length; b++)
                if (kept[b] != null)
                    m_Shader.SetBuffer(copyBack, "_" + FluidComputeLayout.OutPartner((FluidComputeBuffer)b), kept[b]);
            m_Shader.DispatchIndirect(copyBack, Buffer(FluidComputeBuffer.Args), 0);
            Flush();
            for (int b = 0; b < kept.Length; b++)
                if (kept[b] != null)
                {
                    FluidComputeBuffer partner = FluidComputeLayout.OutPartner((FluidComputeBuffer)b);
                    m_Shader.SetBuffer(copyBack, "_" + partner, m_Buffers[(int)partner]);
                    kept[b].Dispose();
                }
        }

        /// <summary>Grows every particle buffer to at least <paramref name="capacity"/> by doubling; the state is kept.</summary>
        public void EnsureCapacity(int capacity)
        {
            if (capacity <= m_Capacity)
                return;
            Allocate(FluidComputeLayout.GrownCapacity(m_Capacity, capacity), m_Cells);
        }

        /// <summary>Uploads the colliders (world space) and drains the following steps use.</summary>
        public void SetShapes(ReadOnlySpan<ColliderShape> colliders, ReadOnlySpan<FluidDrain> drains)
        {
            m_Colliders = colliders.Length;
            m_Drains = drains.Length;
            Allocate(m_Capacity, m_Cells);
            FluidComputeStep.PackShapes(colliders, drains, Buffer(FluidComputeBuffer.Shapes).As<float4>());
        }

        /// <summary>The constants of a step of <paramref name="dt"/> with substeps of <paramref name="h"/>, with this solver's shapes.</summary>
        public FluidComputeConstants ConstantsOf(float h, float dt) => FluidComputeConstants.Of(m_Constants, h, dt, m_Colliders, m_Drains);

        /// <summary>Marks the particles inside a drain (the next step's sort removes them), like <see cref="FluidDrain.Apply"/>.</summary>
        /// <summary>FluidComputeSolver.PackRender: the renderer's float4 per slot.</summary>
        public void PackRender()
        {
            var self = this;
            FluidComputeStep.RecordPackRender(ref self, m_Capacity);
            Flush();
        }

        public void Drain()
        {
            var self = this;
            FluidComputeStep.RecordDrain(ref self, ConstantsOf(0f, 0f));
            Flush();
        }

        /// <summary>Copies the first <paramref name="count"/> particles to the GPU (growing the buffers if needed).</summary>
        public void Upload(FluidParticles p, int count)
        {
            EnsureCapacity(count);
            FluidComputeStep.Pack(p, count, Buffer(FluidComputeBuffer.Positions).As<float4>(), Buffer(FluidComputeBuffer.Velocities).As<float4>(),
                Buffer(FluidComputeBuffer.Extras).As<FluidComputeExtras>());
            Stats.Clear();
            Stats[FluidComputeLayout.StatLive] = (uint)count;
            WriteArgs(count);
        }

        void WriteArgs(int count)
        {
            Span<uint> args = Buffer(FluidComputeBuffer.Args).As<uint>();
            args[0] = (uint)((count + FluidComputeLayout.ThreadGroupSize - 1) / FluidComputeLayout.ThreadGroupSize);
            args[1] = 1;
            args[2] = 1;
        }

        /// <summary>Copies the live particles back; returns their count.</summary>
        public int Download(FluidParticles p)
        {
            int count = Count;
            FluidComputeStep.Unpack(Buffer(FluidComputeBuffer.Positions).As<float4>(), Buffer(FluidComputeBuffer.Velocities).As<float4>(),
                Buffer(FluidComputeBuffer.Extras).As<FluidComputeExtras>(), count, p);
            return count;
        }

        /// <summary>Appends particles (at most the capacity, growing it by doubling first) the way a tap's commands do.</summary>
        public void Emit(FluidParticles spawn, int spawnCount)
        {
            EnsureCapacity(Count + spawnCount);
            FluidComputeStep.Pack(spawn, spawnCount, Buffer(FluidComputeBuffer.PositionsOut).As<float4>(),
                Buffer(FluidComputeBuffer.VelocitiesOut).As<float4>(), Buffer(FluidComputeBuffer.ExtrasOut).As<FluidComputeExtras>());
            var self = this;
            FluidComputeStep.RecordEmit(ref self, spawnCount, m_Capacity);
            Flush();
        }

        /// <summary>
        /// One step of <paramref name="dt"/> seconds: the passes of <see cref="FluidSolver.Step(in FluidConstants, System.ReadOnlySpan{ColliderShape}, float, FluidParticles, FluidScratch, ref FluidStatus)"/>
        /// on the GPU. Returns the plan's substeps and the counters like <see cref="FluidSolver.Finish"/>.
        /// </summary>
        public FluidStepReport Step(float dt, ref FluidStatus status)
        {
            var self = this;
            if (!(dt > 0f) || !math.isfinite(dt))
                return FluidSolver.Finish(new FluidSolver.Plan(), new FluidPassCounters(), dt, Count, ref status);
            // The fastest speed of the step's start sets the plan (no ageing yet); the second begin ages by the time the plan simulates.
            FluidComputeStep.RecordBegin(ref self, ConstantsOf(0f, 0f));
            Flush();
            float maxSpeed = math.min(math.sqrt(math.asfloat(Stats[FluidComputeLayout.StatMaxSpeedSquared])), m_Constants.Parameters.MaxSpeed);
            FluidSolver.Plan plan = FluidSolver.PlanOf(dt, FluidSolver.Substeps(m_Constants, maxSpeed, FluidComputeLayout.DepthOf(m_Constants, Stats), dt));
            FluidComputeStep.RecordBegin(ref self, ConstantsOf(0f, plan.SimulatedTime));
            Span<FluidPass> passes = stackalloc FluidPass[FluidSubstepPasses.MaxPasses];
            int passCount = FluidSubstepPasses.Write(m_Constants, plan.H, m_Colliders > 0, passes);
            FluidComputeStep.RecordSubsteps(ref self, m_Constants, ConstantsOf(plan.H, plan.SimulatedTime), plan.Substeps, passes.Slice(0, passCount));
            Flush();
            return FluidSolver.Finish(plan, Counters(), dt, Count, ref status);
        }

        /// <summary>The counters of the step so far.</summary>
        public FluidPassCounters Counters()
        {
            Span<uint> s = Stats;
            return new FluidPassCounters
            {
                Killed = (int)s[FluidComputeLayout.StatKilled],
                Expired = (int)s[FluidComputeLayout.StatExpired],
                Invalid = (int)s[FluidComputeLayout.StatInvalid],
                SpeedClamped = (int)s[FluidComputeLayout.StatSpeedClamped],
                OverCompressed = (int)s[FluidComputeLayout.StatOverCompressed],
                NeighbourOverflow = (int)s[FluidComputeLayout.StatNeighbourOverflow],
                MaxDensityRatio = math.asfloat(s[FluidComputeLayout.StatMaxDensityRatio]),
                Contacts = (int)s[FluidComputeLayout.StatContacts],
            };
        }

        /// <summary>Runs what was recorded.</summary>
        public double Flush() => m_Shader.Submit();

        public void BindBuffers()
        {
            for (int b = 0; b < m_Buffers.Length; b++)
                for (int k = 0; k < m_Kernels.Length; k++)
                    m_Shader.SetBuffer(m_Kernels[k], "_" + (FluidComputeBuffer)b, m_Buffers[b]);
        }

        public void SetConstants(in FluidComputeConstants constants) => m_Shader.SetConstantBuffer(FluidComputeConstants.BufferName, constants);
        public void SetInts(FluidComputeGlobal name, int4 value) => m_Shader.SetInts(m_GlobalNames[(int)name], value);

        public void Dispatch(FluidKernel kernel, int threads)
        {
            int k = m_Kernels[(int)kernel];
            int group = m_Shader.ThreadGroupSize(k).x;
            if (threads <= 0)
                return;
            m_Shader.Dispatch(k, (threads + group - 1) / group);
            Timed(kernel);
        }

        public void DispatchIndirect(FluidKernel kernel)
        {
            m_Shader.DispatchIndirect(m_Kernels[(int)kernel], Buffer(FluidComputeBuffer.Args), 0);
            Timed(kernel);
        }

        void Timed(FluidKernel kernel)
        {
            if (!TimeKernels)
                return;
            double ms = m_Shader.Submit();
            KernelMilliseconds.TryGetValue(kernel, out var t);
            KernelMilliseconds[kernel] = (t.Milliseconds + ms, t.Dispatches + 1);
        }

        public void Dispose()
        {
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                m_Buffers[b]?.Dispose();
                m_Buffers[b] = null;
            }
        }
    }
}
