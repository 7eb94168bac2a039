namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The Kuhn (Freudenthal) split of a box into 6 tetrahedra, all sharing the diagonal from corner 0 to corner 7.
    /// Corner c of a box is its minimum corner plus (c &amp; 1, (c &gt;&gt; 1) &amp; 1, (c &gt;&gt; 2) &amp; 1) cell sizes. The tetrahedron
    /// of a permutation (p, q, r) of the axes runs 0 → e_p → e_p + e_q → 7; its signed volume is sign(p, q, r) × cell
    /// volume / 6, so for odd permutations the last two corners are swapped to make all six positive. Every face of
    /// the box is cut along its diagonal through the face's lowest corner, so boxes split this way conform across
    /// shared faces (same diagonal on both sides) wherever they sit in a lattice.
    /// </summary>
    public static class KuhnSplit
    {
        /// <summary>Tetrahedra per box.</summary>
        public const int TetrahedraPerBox = 6;

        /// <summary>Corner indices (0..7) of the 6 tetrahedra, 4 per tetrahedron, positively oriented for boxes with positive sizes.</summary>
        public static readonly int[] Corners =
        {
            0, 1, 3, 7, // x, y, z (even)
            0, 2, 6, 7, // y, z, x (even)
            0, 4, 5, 7, // z, x, y (even)
            0, 1, 7, 5, // x, z, y (odd: 0, 1, 5, 7 swapped)
            0, 2, 7, 3, // y, x, z (odd: 0, 2, 3, 7 swapped)
            0, 4, 7, 6, // z, y, x (odd: 0, 4, 6, 7 swapped)
        };
    }
}
