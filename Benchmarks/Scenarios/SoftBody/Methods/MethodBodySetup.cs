using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What every method of the study is built from: one tetrahedral mesh, one material, the same pins and contact settings.</summary>
    public sealed class MethodBodySetup
    {
        /// <summary>The body: its nodes are the particles of every method.</summary>
        public TetrahedralMesh Mesh;
        /// <summary>The material every method is calibrated to.</summary>
        public ElasticMaterial Material;
        /// <summary>Pinned particles (one flag per node); null = none.</summary>
        public bool[] Pinned;
        /// <summary>Particle radius against colliders (m).</summary>
        public float ParticleRadius;
        /// <summary>Coulomb friction against colliders.</summary>
        public float Friction = 0.5f;
        /// <summary>Characteristic length L of the body for the shape-matching calibration (m; see <see cref="ShapeMatchingCalibration"/>).</summary>
        public float CalibrationLength;
        /// <summary>How the body carries its load, for the shape-matching calibration.</summary>
        public ShapeMatchingCalibration.Load CalibrationLoad = ShapeMatchingCalibration.Load.Bending;
        /// <summary>
        /// Angular frequency (rad/s) of the mode the material's damping ratio ζ refers to, for methods whose damping is set at a
        /// reference frequency (FEM's Rayleigh β = 2ζ/ω_ref); 0 = the method's own estimate.
        /// </summary>
        public float DampingFrequency;

        /// <summary>
        /// A jelly cube of <paramref name="size"/> m with <paramref name="edge"/> nodes per axis (6 tetrahedra per cell),
        /// centred above the origin with its bottom layer one particle radius (half a cell) above the height
        /// <paramref name="bottom"/> (m): resting on a floor there from the first substep. Calibrated in compression.
        /// </summary>
        public static MethodBodySetup JellyCube(float size, int edge, float bottom)
        {
            float radius = 0.5f * size / (edge - 1);
            return new MethodBodySetup
            {
                Mesh = BoxTetrahedra.Create(new float3(size), new int3(edge - 1), new float3(0f, bottom + 0.5f * size + radius, 0f)),
                Material = ElasticMaterial.Jelly,
                ParticleRadius = radius,
                CalibrationLength = size,
                CalibrationLoad = ShapeMatchingCalibration.Load.Compression,
            };
        }

        /// <summary>Lumped masses mᵢ = Σ ρ V_t / 4 over the tetrahedra t that hold node i (kg).</summary>
        public float[] LumpedMasses()
        {
            var m = new float[Mesh.NodeCount];
            foreach (int4 t in Mesh.Tetrahedra)
            {
                float3 a = Mesh.Positions[t.x], b = Mesh.Positions[t.y], c = Mesh.Positions[t.z], d = Mesh.Positions[t.w];
                float quarter = Material.Density * Math.Abs(TetrahedralMesh.SignedVolume(a, b, c, d)) * 0.25f;
                m[t.x] += quarter;
                m[t.y] += quarter;
                m[t.z] += quarter;
                m[t.w] += quarter;
            }
            return m;
        }

        /// <summary>Inverse masses wᵢ (0 for pinned nodes), or null when nothing is pinned.</summary>
        public float[] InverseMasses(float[] masses)
        {
            if (Pinned == null || Array.IndexOf(Pinned, true) < 0)
                return null;
            var w = new float[masses.Length];
            for (int i = 0; i < w.Length; i++)
                w[i] = Pinned[i] ? 0f : 1f / masses[i];
            return w;
        }

        /// <summary>A copy with another material (same mesh, pins and contacts).</summary>
        public MethodBodySetup With(ElasticMaterial material) => new MethodBodySetup
        {
            Mesh = Mesh, Material = material, Pinned = Pinned, ParticleRadius = ParticleRadius, Friction = Friction,
            CalibrationLength = CalibrationLength, CalibrationLoad = CalibrationLoad, DampingFrequency = DampingFrequency,
        };

        /// <summary>A copy with another material whose ζ refers to the mode at <paramref name="dampingFrequency"/> (rad/s).</summary>
        public MethodBodySetup With(ElasticMaterial material, float dampingFrequency)
        {
            MethodBodySetup copy = With(material);
            copy.DampingFrequency = dampingFrequency;
            return copy;
        }
    }
}
