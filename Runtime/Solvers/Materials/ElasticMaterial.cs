using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// A solid material in physical terms, the same for every method: each method maps it to its own parameters by a
    /// stated calibration (<c>MaterialCalibration</c>), so two methods given the same material are comparable.
    /// </summary>
    public struct ElasticMaterial
    {
        /// <summary>Young's modulus E (Pa): stress per unit strain in a uniaxial test. 1e4 = soft jelly, 1e6 = rubber.</summary>
        public float YoungsModulus;
        /// <summary>Poisson ratio ν (dimensionless, 0 ≤ ν &lt; 0.5): lateral contraction per unit stretch. 0.5 = incompressible.</summary>
        public float PoissonRatio;
        /// <summary>Density ρ (kg/m³). Water = 1000.</summary>
        public float Density;
        /// <summary>Damping ratio ζ (dimensionless) of the body's slowest deformation mode: 0 = rings forever, 1 = critically damped.</summary>
        public float DampingRatio;

        /// <summary>First Lamé parameter λ = Eν / ((1 + ν)(1 − 2ν)) (Pa).</summary>
        public float LameLambda => YoungsModulus * PoissonRatio / ((1f + PoissonRatio) * (1f - 2f * PoissonRatio));
        /// <summary>Shear modulus μ = E / (2(1 + ν)) (Pa).</summary>
        public float LameMu => YoungsModulus / (2f * (1f + PoissonRatio));
        /// <summary>Speed of shear waves √(μ/ρ) (m/s): a body of size L wobbles near √(μ/ρ)/(2L) Hz.</summary>
        public float ShearWaveSpeed => math.sqrt(LameMu / Density);
        /// <summary>Speed of pressure (P) waves √((λ + 2μ)/ρ) (m/s): the fastest wave, which limits explicit time steps.</summary>
        public float PressureWaveSpeed => math.sqrt((LameLambda + 2f * LameMu) / Density);

        /// <summary>True when every field is finite and in range (E &gt; 0, 0 ≤ ν &lt; 0.5, ρ &gt; 0, ζ ≥ 0).</summary>
        public bool IsValid => YoungsModulus > 0f && math.isfinite(YoungsModulus) && PoissonRatio >= 0f && PoissonRatio < 0.5f
                               && Density > 0f && math.isfinite(Density) && DampingRatio >= 0f && math.isfinite(DampingRatio);

        public ElasticMaterial(float youngsModulus, float poissonRatio, float density, float dampingRatio)
        {
            YoungsModulus = youngsModulus;
            PoissonRatio = poissonRatio;
            Density = density;
            DampingRatio = dampingRatio;
        }

        /// <summary>Gelatin dessert: E 10 kPa, ν 0.45, 1000 kg/m³, ζ 0.1 (wobbles for several periods).</summary>
        public static ElasticMaterial Jelly => new ElasticMaterial(1e4f, 0.45f, 1000f, 0.1f);
        /// <summary>Soft rubber: E 1 MPa, ν 0.45, 1100 kg/m³, ζ 0.2.</summary>
        public static ElasticMaterial Rubber => new ElasticMaterial(1e6f, 0.45f, 1100f, 0.2f);
        /// <summary>Modelling clay (elastic part): E 100 kPa, ν 0.4, 1800 kg/m³, ζ 0.6 (barely overshoots).</summary>
        public static ElasticMaterial Clay => new ElasticMaterial(1e5f, 0.4f, 1800f, 0.6f);
        /// <summary>Soft tissue: E 30 kPa, ν 0.45, 1050 kg/m³, ζ 0.3.</summary>
        public static ElasticMaterial Flesh => new ElasticMaterial(3e4f, 0.45f, 1050f, 0.3f);
    }
}
