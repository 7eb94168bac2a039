using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The body of the stability study: a cube of <see cref="Cells"/>³ cells (6 tetrahedra each) of one material, its
    /// bottom face (y = −size/2) pinned, under gravity, started from a uniform compression of <see cref="Compression"/>
    /// along y about its bottom face (lateral positions kept). The same cube without pins is the body of the hard cases.
    /// Also the explicit stable steps of the mass-spring network and of the FEM mesh built from it, and the limits a
    /// bounded run must stay within (<see cref="BoundedRun"/>).
    /// </summary>
    public sealed class StabilityCube
    {
        /// <summary>Edge of the cube of the study (m).</summary>
        public const float DefaultSize = 0.1f;
        /// <summary>Cells per edge of the cube of the study.</summary>
        public const int DefaultCells = 4;
        /// <summary>Initial compression along y of the study (fraction of the height).</summary>
        public const float DefaultCompression = 0.1f;
        /// <summary>A bounded run's kinetic energy stays below this many times <see cref="EnergyBudget"/>.</summary>
        public const double KineticEnergyFactor = 10.0;
        /// <summary>A bounded run's shape deviation (<see cref="ShapeDeviation"/>) stays below this many cube sizes.</summary>
        public const double DeformationFactor = 2.0;

        /// <summary>Gravity of the stable-step runs (m/s²).</summary>
        public static readonly float3 Gravity = new float3(0f, -9.81f, 0f);

        /// <summary>The stiff material of the study: E = 10 MPa, ν = 0.45, ρ = 1100 kg/m³, ζ = 0.1 (hard rubber).</summary>
        public static ElasticMaterial StiffMaterial => new ElasticMaterial(1e7f, 0.45f, 1100f, 0.1f);

        /// <summary>Edge of the cube (m).</summary>
        public readonly float Size;
        /// <summary>Cells per edge.</summary>
        public readonly int Cells;
        /// <summary>Initial compression along y (fraction of the height).</summary>
        public readonly float Compression;
        /// <summary>The cube with its bottom face pinned (the stable-step runs).</summary>
        public readonly MethodBodySetup Pinned;
        /// <summary>The same cube with nothing pinned (the hard cases).</summary>
        public readonly MethodBodySetup Free;

        readonly double m_MassSpringStep, m_FemStep;

        /// <param name="compression">Initial compression along y (fraction of the height, in [0, 1)).</param>
        public StabilityCube(ElasticMaterial material, float size = DefaultSize, int cells = DefaultCells, float compression = DefaultCompression)
        {
            Size = size;
            Cells = cells;
            Compression = compression;
            TetrahedralMesh mesh = BoxTetrahedra.Create(new float3(size), new int3(cells), float3.zero);
            Free = new MethodBodySetup
            {
                Mesh = mesh, Material = material, CalibrationLength = size, CalibrationLoad = ShapeMatchingCalibration.Load.Compression,
            };
            Pinned = new MethodBodySetup
            {
                Mesh = mesh, Material = material, CalibrationLength = size, CalibrationLoad = ShapeMatchingCalibration.Load.Compression,
                Pinned = StudyBox.NodesAt(mesh, 1, -0.5f * size, 1e-3f * size / cells),
            };
            m_MassSpringStep = ComputeMassSpringStep(Pinned);
            m_FemStep = ComputeFemStep(Pinned);
        }

        /// <summary>Edge of a cell (m).</summary>
        public float CellSize => Size / Cells;

        /// <summary>Σ mᵢ (kg).</summary>
        public double Mass => Pinned.Material.Density * (double)Size * Size * Size;

        /// <summary>
        /// Strain energy of the initial compression in linear elasticity (J): uniaxial strain ε = <see cref="Compression"/>
        /// with the lateral strains held at zero, U₀ = ½ (λ + 2μ) ε² V. A scale, the same for every method (each stores
        /// its own, somewhat different, energy for the same positions).
        /// </summary>
        public double InitialStrainEnergy
        {
            get
            {
                ElasticMaterial m = Pinned.Material;
                double modulus = m.LameLambda + 2.0 * m.LameMu;
                return 0.5 * modulus * Compression * Compression * Size * Size * Size;
            }
        }

        /// <summary>Work of gravity over one cube size (J): M g L.</summary>
        public double GravityWork => Mass * math.length(Gravity) * Size;

        /// <summary>The energy the run starts with and can gain from gravity (J): U₀ + M g L (the kinetic energy starts at 0).</summary>
        public double EnergyBudget => InitialStrainEnergy + GravityWork;

        /// <summary>Largest kinetic energy of a bounded run (J).</summary>
        public double KineticEnergyLimit => KineticEnergyFactor * EnergyBudget;

        /// <summary>Largest shape deviation of a bounded run (m).</summary>
        public double DeformationLimit => DeformationFactor * Size;

        /// <summary>Places the body at rest, then compresses it by <see cref="Compression"/> along y about its bottom face (pinned nodes stay).</summary>
        public void Start(IMethodBody body)
        {
            body.Place();
            float bottom = -0.5f * Size;
            for (int i = 0; i < body.ParticleCount; i++)
            {
                float3 x = body.RestPositions[i];
                body.Positions[i] = new float3(x.x, bottom + (1f - Compression) * (x.y - bottom), x.z);
                body.Velocities[i] = float3.zero;
            }
            body.StateWritten();
        }

        /// <summary>
        /// Largest stable substep (s) of the explicit mass-spring integrators on the pinned cube:
        /// <see cref="MassSpringStability.MaxStableStep"/> (ω_max by power iteration, with the springs' Rayleigh damping).
        /// </summary>
        public double MassSpringExplicitStep => m_MassSpringStep;

        /// <summary>
        /// Largest stable substep (s) of explicit FEM on the pinned cube: √(β² + 4/ω_max²) − β
        /// (<see cref="FemStability.MaxStableStep(float, float)"/>), ω_max of M⁻¹K₀ and β the Rayleigh coefficient of the
        /// default parameters (<see cref="FemSolver.DampingCoefficient"/>); the same for both material models.
        /// </summary>
        public double FemExplicitStep => m_FemStep;

        static double ComputeMassSpringStep(MethodBodySetup setup)
        {
            var issues = new List<ValidationIssue>();
            MassSpringModelData data = MassSpringModelData.FromMesh(setup.Mesh, setup.Material, MassSpringBuildSettings.Default, issues,
                out _, setup.Pinned) ?? throw new InvalidOperationException("Mass-spring bake failed");
            return MassSpringStability.MaxStableStep(data.AsModel());
        }

        /// <summary>Power iterations for ω_max of the FEM mesh (the default 300 is within 1 %; this is well within the bisection's 5 %).</summary>
        const int k_FemPowerIterations = 3000;

        static double ComputeFemStep(MethodBodySetup setup)
        {
            var issues = new List<ValidationIssue>();
            FemModelData data = FemModelData.Create(setup.Mesh, setup.Material, setup.Pinned, issues)
                                ?? throw new InvalidOperationException("FEM bake failed");
            SoftBodyDynamics.Solvers.FemModel model = data.AsModel();
            float beta = FemSolver.DampingCoefficient(model, FemParameters.Default.Sanitized());
            return FemStability.MaxStableStep(FemStability.MaxFrequency(model, k_FemPowerIterations), beta);
        }
    }
}
