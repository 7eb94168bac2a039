namespace SoftBodyDynamics.Solvers
{
    /// <summary>Deformation modes of meshless shape matching (Müller et al. 2005, §4).</summary>
    public enum ShapeMatchingMode : byte
    {
        /// <summary>Goals follow the best-fit rotation only (§4.1).</summary>
        Rigid = 0,
        /// <summary>Goals blend the volume-preserving linear transform with the rotation by β (§4.3).</summary>
        Linear = 1,
    }
}
