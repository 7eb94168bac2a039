using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Shape-matching parameters for an <see cref="ElasticMaterial"/>: shape matching has no Young's modulus, only the
    /// frequency f of the deformation its goals resist (<see cref="ShapeMatchingParameters.Frequency"/>). A body's
    /// static sag under an acceleration a is ≈ a/ω² in every mode (ω = 2πf), and that of an elastic body scales as
    /// ρ a L² / E, so equal sag needs
    /// <code>
    ///   f = k · √(E/ρ) / L
    /// </code>
    /// with L the body's characteristic bending length (its size for a compact body; L_beam² / thickness for a slender
    /// beam, since a beam of length L_beam and thickness h sags as ρ a L_beam⁴ / (E h²)) and k a dimensionless
    /// coefficient that depends on the mode, β and the cluster layout. The coefficients below were fitted to the static
    /// tip deflection of the method study's clamped 8 : 1 : 1 rubber cantilever (16×2×2 cells, overlapping clusters of
    /// 2 cells, β = <see cref="Beta"/>, small load, against the float64 FEM reference) at 16 substeps. The fit is poor:
    /// the clustered beam's sag is far from ∝ 1/f² and depends on ωh, so after the fit the static tip is still 35–55 %
    /// too soft at 16–64 substeps (Documentation~/choosing-a-method.md): treat the result as a starting point.
    /// The damping ratio is the material's for the slowest mode, scaled to act at f (<see cref="SlowestModeRatio"/>).
    /// </summary>
    public static class ShapeMatchingCalibration
    {
        /// <summary>β the coefficients were fitted with (dimensionless).</summary>
        public const float Beta = 0.5f;

        /// <summary>k of the rigid mode (β unused), clustered body (dimensionless).</summary>
        public const float RigidCoefficient = 28f;
        /// <summary>k of the linear mode at β = <see cref="Beta"/>, clustered body (dimensionless).</summary>
        public const float LinearCoefficient = 28f;
        /// <summary>k of the quadratic mode at β = <see cref="Beta"/>, clustered body (dimensionless).</summary>
        public const float QuadraticCoefficient = 28f;

        /// <summary>
        /// f₁/f: the body's slowest (bending) mode over the calibrated f, for the fitting beam (its Euler–Bernoulli first
        /// frequency over f). Shape matching's ζ acts at f, so the material's ζ (that of the slowest mode) maps to
        /// ζ_SM = ζ · f₁/f: with ζ_SM = ζ the slow mode would be overdamped by f/f₁ and creep.
        /// </summary>
        public const float SlowestModeRatio = 0.0058f;

        /// <summary>The fitted k of <paramref name="mode"/>.</summary>
        public static float Coefficient(ShapeMatchingMode mode) => mode switch
        {
            ShapeMatchingMode.Rigid => RigidCoefficient,
            ShapeMatchingMode.Quadratic => QuadraticCoefficient,
            _ => LinearCoefficient,
        };

        /// <summary>f = k √(E/ρ) / L (Hz) for <paramref name="material"/> and characteristic length <paramref name="length"/> (m).</summary>
        public static float Frequency(in ElasticMaterial material, float length, float coefficient) =>
            coefficient * math.sqrt(material.YoungsModulus / material.Density) / length;

        /// <summary>
        /// Parameters for <paramref name="material"/> on a body of characteristic length <paramref name="length"/> (m) in
        /// <paramref name="mode"/>: frequency from the fitted coefficient, ζ · <see cref="SlowestModeRatio"/>, β =
        /// <see cref="Beta"/>, everything else from <paramref name="defaults"/>. The material must be valid
        /// (<see cref="ElasticMaterial.IsValid"/>, as for mass-spring and FEM) and the length finite and above 0: otherwise this
        /// throws an <see cref="System.ArgumentException"/> that says which value is wrong.
        /// </summary>
        public static ShapeMatchingParameters For(in ElasticMaterial material, float length, ShapeMatchingMode mode,
            in ShapeMatchingParameters defaults)
        {
            if (!material.IsValid)
                throw new System.ArgumentException(
                    $"The material is invalid (E = {material.YoungsModulus} Pa, ν = {material.PoissonRatio}, ρ = {material.Density} kg/m³, " +
                    $"ζ = {material.DampingRatio}): use E > 0, 0 ≤ ν < 0.5, ρ > 0 and ζ ≥ 0, all finite — the rule of every method.", nameof(material));
            if (!(length > 0f) || !math.isfinite(length))
                throw new System.ArgumentException($"The characteristic length is {length} m: it must be finite and above 0 m.", nameof(length));
            ShapeMatchingParameters p = defaults;
            p.Mode = mode;
            p.Frequency = Frequency(material, length, Coefficient(mode));
            p.DampingRatio = material.DampingRatio * SlowestModeRatio;
            p.Beta = mode == ShapeMatchingMode.Rigid ? 0f : Beta;
            return p;
        }
    }
}
