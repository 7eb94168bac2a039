namespace SoftBodyDynamics.Solvers
{
    /// <summary>The polynomial order of a finite-element body's tetrahedra (chosen at bake time).</summary>
    public enum FemElementOrder
    {
        /// <summary>Linear 4-node tetrahedra: constant strain per element. Cheapest per element, but stiff in bending (locking): a thin beam needs many elements across.</summary>
        Linear = 1,
        /// <summary>Quadratic 10-node tetrahedra (<see cref="QuadraticTet"/>): linear strain per element, bending without locking; ~10× the work per element, far fewer elements for the same error.</summary>
        Quadratic = 2,
    }
}
