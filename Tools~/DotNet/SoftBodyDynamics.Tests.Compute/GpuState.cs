using System;
using SoftBodyDynamics.Lavapipe;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>Copies a CPU fluid (particles and scratch) to the GPU buffers and back, so one pass can run on both from the same input.</summary>
    static class GpuState
    {
        public static void Upload(LavapipeFluidSolver g, FluidBuffers b, int count, int cells)
        {
            g.Upload(b.Particles, count);
            Put(b.Previous, g.Buffer(FluidComputeBuffer.Previous).As<float4>());
            // The CPU keeps the Jacobi iterates' w, the viscosity renormalization, in the float scratch (FluidPasses.ViscosityIteration).
            Put(b.VectorsA, b.Floats, g.Buffer(FluidComputeBuffer.VectorsA).As<float4>());
            Put(b.VectorsB, b.Floats, g.Buffer(FluidComputeBuffer.VectorsB).As<float4>());
            b.Densities.AsSpan().CopyTo(g.Buffer(FluidComputeBuffer.Densities).As<float>());
            b.Pressures.AsSpan().CopyTo(g.Buffer(FluidComputeBuffer.Pressures).As<float>());
            b.NeighbourCounts.AsSpan().CopyTo(g.Buffer(FluidComputeBuffer.NeighbourCounts).As<int>());
            b.Neighbours.AsSpan().CopyTo(g.Buffer(FluidComputeBuffer.Neighbours).As<int>());
            b.CellStart.AsSpan(0, cells + 2).CopyTo(g.Buffer(FluidComputeBuffer.CellStart).As<int>());
            b.Order.AsSpan().CopyTo(g.Buffer(FluidComputeBuffer.Order).As<int>());
        }

        /// <summary>A CPU fluid holding the GPU's state (count from the GPU's live count).</summary>
        public static FluidBuffers Download(LavapipeFluidSolver g, in FluidConstants c, int capacity, int cells)
        {
            var b = new FluidBuffers(capacity, c.Grid);
            int count = g.Download(b.Particles);
            b.Status.Count = count;
            Get(g.Buffer(FluidComputeBuffer.Previous).As<float4>(), b.Previous);
            Get(g.Buffer(FluidComputeBuffer.VectorsA).As<float4>(), b.VectorsA);
            Get(g.Buffer(FluidComputeBuffer.VectorsB).As<float4>(), b.VectorsB);
            g.Buffer(FluidComputeBuffer.Densities).As<float>().Slice(0, capacity).CopyTo(b.Densities);
            g.Buffer(FluidComputeBuffer.Pressures).As<float>().Slice(0, capacity).CopyTo(b.Pressures);
            g.Buffer(FluidComputeBuffer.NeighbourCounts).As<int>().Slice(0, capacity).CopyTo(b.NeighbourCounts);
            g.Buffer(FluidComputeBuffer.Neighbours).As<int>().Slice(0, b.Neighbours.Length).CopyTo(b.Neighbours);
            g.Buffer(FluidComputeBuffer.CellStart).As<int>().Slice(0, cells + 2).CopyTo(b.CellStart.AsSpan(0, cells + 2));
            g.Buffer(FluidComputeBuffer.Order).As<int>().Slice(0, capacity).CopyTo(b.Order);
            return b;
        }

        static void Put(float3[] source, Span<float4> destination)
        {
            for (int i = 0; i < source.Length; i++)
                destination[i] = new float4(source[i], 0f);
        }

        static void Put(float3[] source, float[] w, Span<float4> destination)
        {
            for (int i = 0; i < source.Length; i++)
                destination[i] = new float4(source[i], w[i]);
        }

        /// <summary>The w of the GPU's vector scratch <paramref name="buffer"/> (the viscosity renormalization after a viscosity pass into it).</summary>
        public static float[] W(LavapipeFluidSolver g, FluidComputeBuffer buffer, int capacity)
        {
            Span<float4> source = g.Buffer(buffer).As<float4>();
            var w = new float[capacity];
            for (int i = 0; i < capacity; i++)
                w[i] = source[i].w;
            return w;
        }

        static void Get(Span<float4> source, float3[] destination)
        {
            for (int i = 0; i < destination.Length; i++)
                destination[i] = source[i].xyz;
        }

        /// <summary>Largest |a − b| over the first <paramref name="count"/> elements, and the largest |b| (the field's scale).</summary>
        public static (double Difference, double Scale) Compare(float3[] a, float3[] b, int count)
        {
            double d = 0, s = 0;
            for (int i = 0; i < count; i++)
            {
                d = Math.Max(d, math.length(a[i] - b[i]));
                s = Math.Max(s, math.length(b[i]));
            }
            return (d, s);
        }

        public static (double Difference, double Scale) Compare(float[] a, float[] b, int count)
        {
            double d = 0, s = 0;
            for (int i = 0; i < count; i++)
            {
                d = Math.Max(d, Math.Abs(a[i] - b[i]));
                s = Math.Max(s, Math.Abs(b[i]));
            }
            return (d, s);
        }
    }
}
