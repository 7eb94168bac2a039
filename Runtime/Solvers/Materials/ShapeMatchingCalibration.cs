using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Shape-matching parameters for an <see cref="ElasticMaterial"/>: shape matching has no Young's modulus, only the
    /// frequency f of the deformation its goals resist (<see cref="ShapeMatchingParameters.Frequency"/>), and its damping
    /// ratio acts at f. Two load cases, because a clustered body's stiffness depends on how it carries its load:
    /// <list type="bullet">
    /// <item><see cref="Load.Compression"/>, a compact body resting on its base (a cube on the floor, a squashed cube): f is
    /// the material's slowest mode, the quarter wave of a column of height H on its base, f = √(E/ρ) / (4H), and ζ_SM = ζ,
    /// the material's ratio for that mode. Overlapping clusters make the body softer than one cluster: its slowest mode
    /// falls below f (a 4-cell cube of 2-cell clusters rings at 0.46 f) and its static sag grows with the clusters across
    /// (documented in Documentation~/choosing-a-method.md); those slower modes decay at the same rate ζω as f, so they are
    /// damped more, not less.</item>
    /// <item><see cref="Load.Bending"/>, a slender body held at one end: f = k √(E/ρ) / L with L = L_beam² / thickness
    /// (a beam sags as ρ a L_beam⁴ / (E h²)) and k fitted to the static tip deflection of the method study's clamped
    /// 8 : 1 : 1 rubber cantilever (16×2×2 cells, overlapping clusters of 2 cells, β = <see cref="Beta"/>, small load,
    /// against the float64 FEM reference) at 16 substeps. The fit is poor: the clustered beam's sag is far from ∝ 1/f² and
    /// depends on ωh, so after the fit the static tip is still 35–55 % too soft at 16–64 substeps
    /// (Documentation~/choosing-a-method.md): treat the result as a starting point. The beam's slowest (bending) mode is
    /// far below f, so ζ_SM = ζ · <see cref="SlowestModeRatio"/>.</item>
    /// </list>
    /// </summary>
    public static class ShapeMatchingCalibration
    {
        /// <summary>How the calibrated body carries its load, which sets the length its stiffness scales with.</summary>
        public enum Load
        {
            /// <summary>A slender body held at one end; the length is L_beam² / thickness (m).</summary>
            Bending,
            /// <summary>A compact body resting on its base; the length is its height along the load (m).</summary>
            Compression,
        }

        /// <summary>f H / √(E/ρ) = 1/4 of a body in <see cref="Load.Compression"/>: the quarter wave of a column on its base (dimensionless).</summary>
        public const float CompressionCoefficient = 0.25f;

        /// <summary>β of the calibrated linear and quadratic modes; the bending coefficients were fitted with it (dimensionless).</summary>
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

        /// <summary>k of <paramref name="mode"/> under <paramref name="load"/>: f = k √(E/ρ) / L.</summary>
        public static float Coefficient(Load load, ShapeMatchingMode mode) => load == Load.Compression ? CompressionCoefficient : mode switch
        {
            ShapeMatchingMode.Rigid => RigidCoefficient,
            ShapeMatchingMode.Quadratic => QuadraticCoefficient,
            _ => LinearCoefficient,
        };

        /// <summary>f = k √(E/ρ) / L (Hz) for <paramref name="material"/> and characteristic length <paramref name="length"/> (m).</summary>
        public static float Frequency(in ElasticMaterial material, float length, float coefficient) =>
            coefficient * math.sqrt(material.YoungsModulus / material.Density) / length;

        /// <summary>
        /// Parameters for <paramref name="material"/> on a body of characteristic length <paramref name="length"/> (m) carrying
        /// its load by <paramref name="load"/>, in <paramref name="mode"/>: its frequency and damping ratio (above), β =
        /// <see cref="Beta"/>, everything else from <paramref name="defaults"/>. The material must be valid
        /// (<see cref="ElasticMaterial.IsValid"/>, as for mass-spring and FEM), the length finite and above 0, and the frequency
        /// at most <see cref="ShapeMatchingParameters.MaxFrequency"/>: otherwise this throws an <see cref="System.ArgumentException"/>
        /// that says which value is wrong.
        /// </summary>
        public static ShapeMatchingParameters For(in ElasticMaterial material, float length, Load load, ShapeMatchingMode mode,
            in ShapeMatchingParameters defaults)
        {
            if (!material.IsValid)
                throw new System.ArgumentException(
                    $"The material is invalid (E = {material.YoungsModulus} Pa, ν = {material.PoissonRatio}, ρ = {material.Density} kg/m³, " +
                    $"ζ = {material.DampingRatio}): use E > 0, 0 ≤ ν < 0.5, ρ > 0 and ζ ≥ 0, all finite — the rule of every method.", nameof(material));
            if (!(length > 0f) || !math.isfinite(length))
                throw new System.ArgumentException($"The characteristic length is {length} m: it must be finite and above 0 m.", nameof(length));
            float frequency = Frequency(material, length, Coefficient(load, mode));
            if (!(frequency <= ShapeMatchingParameters.MaxFrequency))
                throw new System.ArgumentException(
                    $"This material on a body of {length} m ({load}) needs a frequency of {frequency:0} Hz, above the {ShapeMatchingParameters.MaxFrequency:0} Hz " +
                    "shape matching accepts: it is too stiff for shape matching at this size; use FEM (implicit) or a softer material.", nameof(material));
            ShapeMatchingParameters p = defaults;
            p.Mode = mode;
            p.Frequency = frequency;
            p.DampingRatio = material.DampingRatio * (load == Load.Compression ? 1f : SlowestModeRatio);
            p.Beta = mode == ShapeMatchingMode.Rigid ? 0f : Beta;
            return p;
        }
    }
}
