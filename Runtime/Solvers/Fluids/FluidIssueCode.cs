namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Problems of a fluid's parameters and of its baking (<see cref="FluidValidation"/>, the fluid baker).
    /// The numbers are unique across domains and stable (they may be stored); new codes take new numbers. An
    /// <see cref="IssueCode"/> carries any domain's code.
    /// </summary>
    public enum FluidIssueCode
    {
        /// <summary>The particle spacing is not a positive finite length (m).</summary>
        SpacingInvalid = 200,
        /// <summary>The kernel radius ratio h/Δx is outside 1.5–4 (too few or far too many neighbours).</summary>
        KernelRatioInvalid = 201,
        /// <summary>The rest density is not a positive finite value (kg/m³).</summary>
        DensityInvalid = 202,
        /// <summary>The speed of sound is not positive and finite, or absurd (above 1500 m/s, the real value for water, which would need thousands of substeps).</summary>
        SpeedOfSoundInvalid = 203,
        /// <summary>The domain box is not finite or is smaller than one kernel radius along some axis.</summary>
        DomainInvalid = 204,
        /// <summary>The domain holds more grid cells than the grid allows (<c>FluidGrid.MaxCells</c>): the cells get coarser and the neighbour search slower. Shrink the domain or increase the spacing.</summary>
        GridTooLarge = 205,
        /// <summary>The particle budget is not positive.</summary>
        BudgetInvalid = 206,
        /// <summary>Viscosity, cohesion, separation, alignment or surface tension is negative or not finite.</summary>
        CoefficientInvalid = 207,
        /// <summary>Warning: the CFL limit asks for more substeps per 1/60 s frame than the cap allows even for a fluid at rest; the step will run capped (and report it). Lower the speed of sound or raise the cap.</summary>
        SubstepCapTooLow = 208,
        /// <summary>A fluid with Entities storage has no particle prefab to instantiate.</summary>
        PrefabMissing = 233,
        /// <summary>A fluid asks for the GPU but no compute shader is assigned: it runs on the CPU.</summary>
        ComputeShaderMissing = 234,
        /// <summary>A fluid with Entities storage asks for the GPU: one entity per particle needs the CPU path.</summary>
        GpuNeedsPackedStorage = 235,
        /// <summary>The GPU read-back interval is below one frame.</summary>
        ReadbackIntervalInvalid = 236,
        /// <summary>Warning: a periodic axis of the fluid's domain is shorter than three kernel radii, so it is not periodic.</summary>
        PeriodicAxisTooShort = 241,
        /// <summary>Warning: the fluid's implicit viscosity needs more Jacobi iterations than a substep runs to converge at its substep (a steady flow then runs too fast).</summary>
        ViscosityUnresolved = 242,
        /// <summary>Warning: a fluid's wall friction μ or no-slip share (colliders or domain faces) is outside [0, 1] or NaN; the step clamps it.</summary>
        WallShareOutOfRange = 243,
    }
}
