using System;
using System.Collections.Generic;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Elements (springs, tetrahedra) split into colours such that no two elements of one colour share a particle: the
    /// elements of one colour can be projected in parallel (Gauss–Seidel per colour) with no write conflict, and the
    /// result is the same for any worker count. Greedy in element order (deterministic); elements keep their
    /// relative order inside a colour. Built at bake time.
    /// </summary>
    public sealed class GraphColoring
    {
        /// <summary>Colour c holds <see cref="Elements"/>[ColorOffsets[c] .. ColorOffsets[c + 1]).</summary>
        public int[] ColorOffsets;
        /// <summary>Element indices grouped by colour.</summary>
        public int[] Elements;

        public int ColorCount => ColorOffsets.Length - 1;

        /// <summary>Colours the elements whose corners are <paramref name="elementCorners"/> (<paramref name="cornersPerElement"/> per element).</summary>
        public static GraphColoring Build(ReadOnlySpan<int> elementCorners, int cornersPerElement, int particleCount)
        {
            if (cornersPerElement <= 0 || elementCorners.Length % cornersPerElement != 0)
                throw new ArgumentException("The corner list is not a whole number of elements.", nameof(elementCorners));
            int elementCount = elementCorners.Length / cornersPerElement;
            var color = new int[elementCount];
            // Colours used at each particle, as a bit mask per 64 colours (a particle of valence v needs at most v colours).
            var masks = new ulong[particleCount];
            var overflow = new Dictionary<long, bool>();
            int colorCount = 0;
            for (int e = 0; e < elementCount; e++)
            {
                int c = 0;
                while (true)
                {
                    bool free = true;
                    for (int k = 0; k < cornersPerElement && free; k++)
                        free = !Uses(masks, overflow, elementCorners[e * cornersPerElement + k], c);
                    if (free)
                        break;
                    c++;
                }
                color[e] = c;
                for (int k = 0; k < cornersPerElement; k++)
                    Mark(masks, overflow, elementCorners[e * cornersPerElement + k], c);
                colorCount = Math.Max(colorCount, c + 1);
            }
            var offsets = new int[colorCount + 1];
            for (int e = 0; e < elementCount; e++)
                offsets[color[e] + 1]++;
            for (int c = 0; c < colorCount; c++)
                offsets[c + 1] += offsets[c];
            var fill = new int[colorCount];
            var elements = new int[elementCount];
            for (int e = 0; e < elementCount; e++)
                elements[offsets[color[e]] + fill[color[e]]++] = e;
            return new GraphColoring { ColorOffsets = offsets, Elements = elements };
        }

        static bool Uses(ulong[] masks, Dictionary<long, bool> overflow, int particle, int c) =>
            c < 64 ? (masks[particle] & (1ul << c)) != 0 : overflow.ContainsKey(((long)particle << 32) | (uint)c);

        static void Mark(ulong[] masks, Dictionary<long, bool> overflow, int particle, int c)
        {
            if (c < 64)
                masks[particle] |= 1ul << c;
            else
                overflow[((long)particle << 32) | (uint)c] = true;
        }
    }
}
