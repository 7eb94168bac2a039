namespace SoftBodyDynamics.Solvers
{
    /// <summary>How a finite-element body is baked from its tetrahedra (authoring → <see cref="FemModelData"/>).</summary>
    public struct FemBuildSettings
    {
        /// <summary>Constitutive model (for the explicit stable step the bake reports).</summary>
        public FemMaterialModel Model;
        /// <summary>Linear (4-node) or quadratic (10-node) tetrahedra.</summary>
        public FemElementOrder Order;
        /// <summary>Bake the <see cref="FemRestFactor"/> preconditioner of the implicit step (memory: ~3 × bandwidth floats per node row).</summary>
        public bool RestFactor;
        /// <summary>The substep h (s) the rest factor is built for (fixed step / substeps); another h works, with more iterations.</summary>
        public float Substep;
        /// <summary>Rayleigh reference frequency (rad/s) of the body's parameters (0 = the model's estimate), for the factor's β.</summary>
        public float DampingFrequency;

        /// <summary>Linear co-rotational elements, no rest factor.</summary>
        public static FemBuildSettings Default => new FemBuildSettings { Model = FemMaterialModel.CoRotational, Order = FemElementOrder.Linear };

        /// <summary>True when the two bake the same model.</summary>
        public bool SameAs(in FemBuildSettings other) => Model == other.Model && Order == other.Order && RestFactor == other.RestFactor
            && Substep.Equals(other.Substep) && DampingFrequency.Equals(other.DampingFrequency);
    }
}
