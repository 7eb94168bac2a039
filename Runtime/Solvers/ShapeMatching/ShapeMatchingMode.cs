namespace SoftBodyDynamics.Solvers
{
    /// <summary>Deformation modes of meshless shape matching (Müller et al. 2005, §4).</summary>
    public enum ShapeMatchingMode : byte
    {
        /// <summary>Goals follow the best-fit rotation only (§4.1): stiff, volume exact, cheapest.</summary>
        Rigid = 0,
        /// <summary>Goals blend the volume-preserving linear transform with the rotation by β (§4.3): shear and stretch.</summary>
        Linear = 1,
        /// <summary>Goals blend a quadratic transform (3×9, §4.4) with the rotation by β: bending and twisting of one cluster.</summary>
        Quadratic = 2,
    }
}
