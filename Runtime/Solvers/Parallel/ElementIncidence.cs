using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// For each particle, the element corners that touch it, in increasing slot order (slot = element × corners per
    /// element + corner). It turns a pass over elements into a deterministic parallel sum: the element pass writes one
    /// value per slot (elements in any order, on any worker), then <see cref="Gather"/> adds each particle's slots in
    /// this fixed order. The sum has the same bits for any split of either pass among workers. Built at bake time.
    /// </summary>
    public sealed class ElementIncidence
    {
        /// <summary>Slots of particle i are <see cref="Slots"/>[Offsets[i] .. Offsets[i + 1]).</summary>
        public int[] Offsets;
        /// <summary>Slot indices, grouped by particle, increasing within a particle.</summary>
        public int[] Slots;

        /// <summary>The incidence of <paramref name="elementCorners"/> (element e's corner k is entry e × <paramref name="cornersPerElement"/> + k).</summary>
        public static ElementIncidence Build(ReadOnlySpan<int> elementCorners, int cornersPerElement, int particleCount)
        {
            if (cornersPerElement <= 0 || elementCorners.Length % cornersPerElement != 0)
                throw new ArgumentException("The corner list is not a whole number of elements.", nameof(elementCorners));
            var offsets = new int[particleCount + 1];
            for (int s = 0; s < elementCorners.Length; s++)
            {
                int p = elementCorners[s];
                if ((uint)p >= (uint)particleCount)
                    throw new ArgumentOutOfRangeException(nameof(elementCorners), $"Corner {s} refers to particle {p} of {particleCount}.");
                offsets[p + 1]++;
            }
            for (int i = 0; i < particleCount; i++)
                offsets[i + 1] += offsets[i];
            var fill = new int[particleCount];
            var slots = new int[elementCorners.Length];
            // Slots in increasing order, so each particle's list is sorted.
            for (int s = 0; s < elementCorners.Length; s++)
            {
                int p = elementCorners[s];
                slots[offsets[p] + fill[p]++] = s;
            }
            return new ElementIncidence { Offsets = offsets, Slots = slots };
        }

        /// <summary>
        /// resultᵢ += Σ perSlot[slot] over particle i's slots, for particles [<paramref name="start"/>, <paramref name="end"/>),
        /// summed in slot order (the same bits however the particles are split among workers).
        /// </summary>
        public static void Gather(ReadOnlySpan<int> offsets, ReadOnlySpan<int> slots, ReadOnlySpan<float3> perSlot, int start, int end,
            Span<float3> result)
        {
            for (int i = start; i < end; i++)
            {
                float3 sum = float3.zero;
                for (int k = offsets[i]; k < offsets[i + 1]; k++)
                    sum += perSlot[slots[k]];
                result[i] += sum;
            }
        }
    }
}
