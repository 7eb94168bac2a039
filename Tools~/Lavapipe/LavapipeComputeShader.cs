using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Lavapipe
{
    /// <summary>
    /// Unity's <c>ComputeShader</c> on lavapipe: kernels found by name, buffers bound per kernel by name (the binding
    /// numbers come from each kernel's reflection), loose globals set by name and packed by the reflected offsets into a
    /// uniform block per dispatch, named constant buffers (HLSL <c>cbuffer</c>) bound as uniform buffers by name. Dispatches
    /// are recorded until <see cref="Submit"/>.
    /// </summary>
    public sealed unsafe class LavapipeComputeShader : IDisposable
    {
        sealed class Kernel
        {
            public CompiledKernel Compiled;
            public IntPtr Handle;
            public LavapipeBuffer[] Buffers;
            public int GlobalSlot = -1;
            public (int Global, int Offset)[] GlobalLayout;
            /// <summary>The binding slots of the kernel's named constant buffers, with their names.</summary>
            public List<(int Slot, string Name)> ConstantSlots = new List<(int, string)>();
        }

        /// <summary>A constant buffer's bytes and where they sit in the arena until the next submit.</summary>
        sealed class Constants
        {
            public byte[] Data;
            public long Offset;
        }

        readonly LavapipeDevice m_Device;
        readonly List<Kernel> m_Kernels = new List<Kernel>();
        readonly Dictionary<string, int> m_GlobalIndex = new Dictionary<string, int>();
        readonly List<(float4 Value, bool Set)> m_Globals = new List<(float4, bool)>();
        readonly Dictionary<string, Constants> m_Constants = new Dictionary<string, Constants>();
        readonly LavapipeBuffer m_Arena;
        long m_ArenaCursor;
        const long ArenaBytes = 8 << 20;

        /// <summary>Dispatches recorded since the last submit.</summary>
        public int Recorded { get; private set; }

        /// <summary>Compiles <paramref name="computePath"/> with <paramref name="defines"/> added to every kernel.</summary>
        public LavapipeComputeShader(LavapipeDevice device, string computePath, params string[] defines)
        {
            m_Device = device;
            m_Arena = device.CreateBuffer(ArenaBytes);
            int* bindings = stackalloc int[64];
            int* kinds = stackalloc int[64];
            byte* error = stackalloc byte[512];
            foreach (CompiledKernel ck in KernelCompiler.Compile(computePath, defines))
            {
                var k = new Kernel { Compiled = ck, Buffers = new LavapipeBuffer[ck.Bindings.Count] };
                int n = ck.Bindings.Count;
                if (n > 64)
                    throw new InvalidOperationException($"{ck.Name}: more than 64 resources");
                for (int b = 0; b < n; b++)
                {
                    bindings[b] = ck.Bindings[b].Binding;
                    kinds[b] = ck.Bindings[b].Uniform ? 1 : 0;
                    if (ck.Bindings[b].Uniform && ck.Bindings[b].Name == "$Global")
                        k.GlobalSlot = b;
                    else if (ck.Bindings[b].Uniform)
                        k.ConstantSlots.Add((b, ck.Bindings[b].Name));
                }
                int rc;
                fixed (byte* code = ck.Spirv)
                    rc = VkHost.vkh_kernel_create(device.Context, code, (ulong)ck.Spirv.Length, ck.Name, n, bindings, kinds, out k.Handle, error, 512);
                if (rc != 0)
                    throw new InvalidOperationException($"{ck.Name}: {Marshal.PtrToStringUTF8((IntPtr)error)}");
                var layout = new List<(int, int)>();
                foreach (var pair in ck.GlobalOffsets)
                    layout.Add((GlobalIndex(pair.Key), pair.Value));
                k.GlobalLayout = layout.ToArray();
                m_Kernels.Add(k);
            }
        }

        int GlobalIndex(string name)
        {
            if (!m_GlobalIndex.TryGetValue(name, out int index))
            {
                index = m_Globals.Count;
                m_GlobalIndex[name] = index;
                m_Globals.Add((default, false));
            }
            return index;
        }

        public int KernelCount => m_Kernels.Count;
        public string KernelName(int kernel) => m_Kernels[kernel].Compiled.Name;
        public CompiledKernel Compiled(int kernel) => m_Kernels[kernel].Compiled;

        /// <summary>ComputeShader.FindKernel.</summary>
        public int FindKernel(string name)
        {
            for (int i = 0; i < m_Kernels.Count; i++)
                if (m_Kernels[i].Compiled.Name == name)
                    return i;
            throw new ArgumentException($"no kernel {name}");
        }

        /// <summary>ComputeShader.GetKernelThreadGroupSizes.</summary>
        public int3 ThreadGroupSize(int kernel) =>
            new int3(m_Kernels[kernel].Compiled.GroupSizeX, m_Kernels[kernel].Compiled.GroupSizeY, m_Kernels[kernel].Compiled.GroupSizeZ);

        /// <summary>ComputeShader.SetBuffer: a name the kernel does not use is ignored, as in Unity.</summary>
        public void SetBuffer(int kernel, string name, LavapipeBuffer buffer)
        {
            Kernel k = m_Kernels[kernel];
            for (int b = 0; b < k.Compiled.Bindings.Count; b++)
                if (!k.Compiled.Bindings[b].Uniform && k.Compiled.Bindings[b].Name == name)
                    k.Buffers[b] = buffer;
        }

        /// <summary>ComputeShader.SetVector for a loose global.</summary>
        public void SetVector(string name, float4 value) => m_Globals[GlobalIndex(name)] = (value, true);

        /// <summary>ComputeShader.SetInts for an int4 / uint4 loose global.</summary>
        public void SetInts(string name, int4 value) =>
            m_Globals[GlobalIndex(name)] = (new float4(math.asfloat(value.x), math.asfloat(value.y), math.asfloat(value.z), math.asfloat(value.w)), true);

        /// <summary>
        /// ComputeShader.SetConstantBuffer of a <c>GraphicsBuffer.Target.Constant</c> buffer just filled with
        /// <paramref name="value"/> by GraphicsBuffer.SetData: the cbuffer <paramref name="name"/> of every kernel reads
        /// these bytes from the next dispatch on. The bytes are copied now, so dispatches recorded before keep the
        /// earlier contents, in the order Unity runs SetData and dispatches.
        /// </summary>
        public void SetConstantBuffer<T>(string name, in T value) where T : unmanaged
        {
            var data = new byte[sizeof(T)];
            MemoryMarshal.Write(data, in value);
            if (data.Length % 16 != 0)
                throw new ArgumentException($"constant buffer {name}: {data.Length} bytes is not a multiple of 16");
            var constants = new Constants { Data = data };
            Place(constants);
            m_Constants[name] = constants;
        }

        /// <summary>Copies a constant buffer's bytes to the next aligned block of the arena.</summary>
        void Place(Constants constants)
        {
            long size = Aligned(constants.Data.Length);
            if (m_ArenaCursor + size > m_Arena.Bytes)
                throw new InvalidOperationException("uniform arena full: submit more often");
            constants.Data.CopyTo(m_Arena.As<byte>().Slice((int)m_ArenaCursor, constants.Data.Length));
            constants.Offset = m_ArenaCursor;
            m_ArenaCursor += size;
        }

        // 256 bytes: the largest minUniformBufferOffsetAlignment Vulkan allows, so every block offset is aligned.
        static long Aligned(long bytes) => (bytes + 255) & ~255L;

        public void Dispatch(int kernel, int groupsX, int groupsY = 1, int groupsZ = 1) => Record(kernel, (uint)groupsX, (uint)groupsY, (uint)groupsZ, null, 0);

        /// <summary>ComputeShader.DispatchIndirect with the group counts at <paramref name="offsetBytes"/> of <paramref name="args"/>.</summary>
        public void DispatchIndirect(int kernel, LavapipeBuffer args, uint offsetBytes) => Record(kernel, 0, 0, 0, args, offsetBytes);

        void Record(int kernel, uint gx, uint gy, uint gz, LavapipeBuffer indirect, uint indirectOffset)
        {
            Kernel k = m_Kernels[kernel];
            int n = k.Buffers.Length;
            IntPtr* handles = stackalloc IntPtr[Math.Max(n, 1)];
            ulong* offsets = stackalloc ulong[Math.Max(n, 1)];
            ulong* ranges = stackalloc ulong[Math.Max(n, 1)];
            if (k.GlobalSlot >= 0)
            {
                long size = Aligned(k.Compiled.GlobalBlockSize);
                if (m_ArenaCursor + size > m_Arena.Bytes)
                    throw new InvalidOperationException("uniform arena full: submit more often");
                Span<byte> block = m_Arena.As<byte>().Slice((int)m_ArenaCursor, k.Compiled.GlobalBlockSize);
                block.Clear();
                foreach (var (global, offset) in k.GlobalLayout)
                {
                    var (value, set) = m_Globals[global];
                    if (!set)
                        continue;
                    MemoryMarshal.Write(block.Slice(offset, Math.Min(16, block.Length - offset)), in value);
                }
                k.Buffers[k.GlobalSlot] = m_Arena;
                offsets[k.GlobalSlot] = (ulong)m_ArenaCursor;
                ranges[k.GlobalSlot] = (ulong)k.Compiled.GlobalBlockSize;
                m_ArenaCursor += size;
            }
            foreach (var (slot, name) in k.ConstantSlots)
            {
                if (!m_Constants.TryGetValue(name, out Constants constants))
                    throw new InvalidOperationException($"{k.Compiled.Name}: constant buffer {name} is not set");
                int declared = k.Compiled.ConstantBlocks[name].Size;
                if (constants.Data.Length < declared)
                    throw new InvalidOperationException($"{k.Compiled.Name}: constant buffer {name} has {constants.Data.Length} bytes, the kernel reads {declared}");
                k.Buffers[slot] = m_Arena;
                offsets[slot] = (ulong)constants.Offset;
                ranges[slot] = (ulong)constants.Data.Length;
            }
            for (int b = 0; b < n; b++)
            {
                if (k.Buffers[b] == null)
                    throw new InvalidOperationException($"{k.Compiled.Name}: buffer {k.Compiled.Bindings[b].Name} is not set");
                handles[b] = k.Buffers[b].Handle;
                if (!k.Compiled.Bindings[b].Uniform)
                {
                    offsets[b] = 0;
                    ranges[b] = 0;
                }
            }
            int rc = VkHost.vkh_dispatch(m_Device.Context, k.Handle, n, handles, offsets, ranges, gx, gy, gz,
                indirect == null ? IntPtr.Zero : indirect.Handle, indirectOffset);
            if (rc != 0)
                throw new InvalidOperationException($"vkh_dispatch({k.Compiled.Name}) failed ({rc})");
            Recorded++;
            if (m_ArenaCursor > m_Arena.Bytes - 4096)
                Submit();
        }

        /// <summary>Runs what was recorded; returns the device milliseconds.</summary>
        public double Submit()
        {
            double ms = m_Device.Submit();
            m_ArenaCursor = 0;
            Recorded = 0;
            // The constant buffers stay bound: their bytes move to the start of the emptied arena.
            foreach (Constants constants in m_Constants.Values)
                Place(constants);
            return ms;
        }

        public void Dispose()
        {
            foreach (Kernel k in m_Kernels)
                if (k.Handle != IntPtr.Zero)
                    VkHost.vkh_kernel_destroy(m_Device.Context, k.Handle);
            m_Kernels.Clear();
            m_Arena.Dispose();
        }
    }
}
