using System;
using SoftBodyDynamics.Compute;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Rendering
{
    /// <summary>
    /// The GPU buffers of one fluid's surface passes (every <see cref="FluidSurfaceBuffer"/> but the particles, which the
    /// simulation owns), its tile-entry capacity, and the read-back of its counters. Buffers are created on first use and
    /// re-created only when the targets or the tile capacity need more elements than they hold; they are never shrunk,
    /// so cameras of different sizes (game and scene views) share them without re-creating them every frame. The kernels
    /// take the live sizes from their constants, so a larger buffer than needed is harmless.
    /// </summary>
    sealed class FluidSurfaceResources : IDisposable
    {
        static readonly int k_BufferCount = Enum.GetValues(typeof(FluidSurfaceBuffer)).Length;

        readonly GraphicsBuffer[] m_Buffers = new GraphicsBuffer[k_BufferCount];
        GpuReadback<uint> m_Readback = new GpuReadback<uint>();

        public FluidSurfaceResources(int initialTileCapacity)
        {
            TileCapacity = Math.Max(initialTileCapacity, 1);
        }

        /// <summary>Tile entries the TileEntries buffer holds (the kernels drop any beyond it, counting them).</summary>
        public int TileCapacity { get; private set; }

        /// <summary>Counters of the last read-back that completed (<see cref="FluidSurfaceLayout"/>.Stat*); zero before the first.</summary>
        public int LastEntries { get; private set; }
        public int LastDropped { get; private set; }

        /// <summary>The constant buffer of the fluid's passes; null before <see cref="Ensure"/>.</summary>
        public FluidSurfaceConstantBuffer Constants { get; private set; }

        /// <summary>The buffer <paramref name="buffer"/>; null for <see cref="FluidSurfaceBuffer.Particles"/> and before <see cref="Ensure"/>.</summary>
        public GraphicsBuffer this[FluidSurfaceBuffer buffer] => m_Buffers[(int)buffer];

        /// <summary>Creates the constant buffer once, and creates, or re-creates larger, every buffer too small for <paramref name="targets"/> and the tile capacity.</summary>
        public void Ensure(in FluidSurfaceTargets targets)
        {
            Constants ??= new FluidSurfaceConstantBuffer();
            for (int b = 0; b < k_BufferCount; b++)
            {
                var id = (FluidSurfaceBuffer)b;
                if (id == FluidSurfaceBuffer.Particles)
                    continue;
                int length = FluidSurfaceLayout.Length(id, targets, 0, TileCapacity);
                GraphicsBuffer old = m_Buffers[b];
                if (old != null && old.IsValid() && old.count >= length)
                    continue;
                old?.Release();
                m_Buffers[b] = new GraphicsBuffer(GraphicsBuffer.Target.Structured, length, FluidSurfaceLayout.Stride(id));
            }
        }

        /// <summary>
        /// Takes the counters of a completed read-back (never waited for; <see cref="GpuReadback{T}"/> keeps them until taken,
        /// in whichever frame they arrived) and asks for the next one, keeping at most one in flight. The request is queued when the renderer records the frame, before the frame's passes run,
        /// so the counters it returns are those of the last frame drawn with these buffers. When the entries needed
        /// exceed the capacity, the capacity grows to the next power of two (the TileEntries buffer follows at the next
        /// <see cref="Ensure"/>) and this returns true with the old capacity in <paramref name="previousCapacity"/>.
        /// </summary>
        public bool PollStats(out int previousCapacity)
        {
            previousCapacity = TileCapacity;
            bool grew = false;
            ReadOnlySpan<uint> stats = m_Readback.Take();
            if (stats.Length >= FluidSurfaceLayout.StatCount)
            {
                LastEntries = (int)Math.Min(stats[FluidSurfaceLayout.StatEntries], (uint)int.MaxValue);
                LastDropped = (int)Math.Min(stats[FluidSurfaceLayout.StatDropped], (uint)int.MaxValue);
                if (LastEntries > TileCapacity)
                {
                    TileCapacity = NextPowerOfTwo(LastEntries);
                    grew = true;
                }
            }
            GraphicsBuffer statsBuffer = m_Buffers[(int)FluidSurfaceBuffer.Stats];
            if (statsBuffer != null && SystemInfo.supportsAsyncGPUReadback)
                m_Readback.Request(statsBuffer);
            return grew;
        }

        /// <summary>The smallest power of two ≥ <paramref name="n"/> (at most 2³⁰).</summary>
        public static int NextPowerOfTwo(int n)
        {
            int p = 1;
            while (p < n && p < 1 << 30)
                p <<= 1;
            return p;
        }

        public void Dispose()
        {
            for (int b = 0; b < m_Buffers.Length; b++)
            {
                m_Buffers[b]?.Release();
                m_Buffers[b] = null;
            }
            Constants?.Dispose();
            Constants = null;
            // A request in flight completes into the disposed copy's nothing; a later Ensure starts afresh.
            m_Readback.Dispose();
            m_Readback = new GpuReadback<uint>();
        }
    }
}
