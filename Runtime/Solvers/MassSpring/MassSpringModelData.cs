using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// Managed storage of a <see cref="MassSpringModel"/>, built once at bake or set-up time. The baker copies these
    /// arrays into a blob; tests and benchmarks use them directly.
    /// </summary>
    public sealed class MassSpringModelData
    {
        /// <summary>Rest positions (m, body space).</summary>
        public float3[] RestPositions;
        /// <summary>Centre of mass of the rest shape (m).</summary>
        public float3 RestCenter;
        /// <summary>Masses (kg).</summary>
        public float[] Masses;
        /// <summary>Inverse masses (1/kg), 0 = pinned.</summary>
        public float[] InverseMasses;
        /// <summary>The springs.</summary>
        public Spring[] Springs;
        /// <summary>Incidence of the springs' two corners (slot 2e = A, 2e + 1 = B).</summary>
        public ElementIncidence Incidence;
        /// <summary>Colours of the springs (no two springs of a colour share a particle).</summary>
        public GraphColoring Coloring;

        public int ParticleCount => RestPositions.Length;
        public int SpringCount => Springs.Length;

        /// <summary>Span views of the arrays.</summary>
        public MassSpringModel AsModel() => new MassSpringModel(RestPositions, RestCenter, Masses, InverseMasses, Springs,
            Incidence.Offsets, Incidence.Slots, Coloring.ColorOffsets, Coloring.Elements);

        /// <summary>
        /// A model over given springs. <paramref name="pinned"/> (may be null) marks particles held in place (inverse
        /// mass 0). Inputs are not validated here: <see cref="MassSpringNetwork.Build"/> and the calibration are.
        /// </summary>
        /// <param name="restPositions">Rest positions (m).</param>
        /// <param name="masses">Masses (kg, &gt; 0).</param>
        /// <param name="springs">Springs with stiffness and damping set.</param>
        /// <param name="pinned">Per particle, true = pinned; null = none.</param>
        public static MassSpringModelData Create(float3[] restPositions, float[] masses, Spring[] springs, bool[] pinned = null)
        {
            int n = restPositions.Length;
            var data = new MassSpringModelData
            {
                RestPositions = (float3[])restPositions.Clone(),
                Masses = (float[])masses.Clone(),
                InverseMasses = new float[n],
                Springs = (Spring[])springs.Clone(),
            };
            double mass = 0.0, cx = 0.0, cy = 0.0, cz = 0.0;
            for (int i = 0; i < n; i++)
            {
                data.InverseMasses[i] = pinned != null && pinned[i] ? 0f : 1f / masses[i];
                mass += masses[i];
                cx += masses[i] * (double)restPositions[i].x;
                cy += masses[i] * (double)restPositions[i].y;
                cz += masses[i] * (double)restPositions[i].z;
            }
            data.RestCenter = mass > 0.0 ? new float3((float)(cx / mass), (float)(cy / mass), (float)(cz / mass)) : float3.zero;
            var corners = new int[2 * springs.Length];
            for (int e = 0; e < springs.Length; e++)
            {
                corners[2 * e] = springs[e].A;
                corners[2 * e + 1] = springs[e].B;
            }
            data.Incidence = ElementIncidence.Build(corners, 2, n);
            data.Coloring = GraphColoring.Build(corners, 2, n);
            return data;
        }

        /// <summary>
        /// Builds the network of <paramref name="mesh"/>, calibrates it to <paramref name="material"/>
        /// (<see cref="MassSpringCalibration.Calibrate"/>) and makes the model; null when an error was reported.
        /// </summary>
        /// <param name="referenceFrequency">ω_ref (rad/s) at which the damping ratio holds; 0 = the default estimate.</param>
        public static MassSpringModelData FromMesh(TetrahedralMesh mesh, in ElasticMaterial material, in MassSpringBuildSettings settings,
            List<ValidationIssue> issues, out MassSpringCalibration.Result calibration, bool[] pinned = null, float referenceFrequency = 0f)
        {
            calibration = default;
            MassSpringNetwork network = MassSpringNetwork.Build(mesh, settings, issues);
            if (network == null)
                return null;
            if (!MassSpringCalibration.Calibrate(network, mesh, material, settings, referenceFrequency, issues, out calibration))
                return null;
            float[] masses = MassSpringCalibration.LumpedMasses(network, material.Density);
            return Create(mesh.Positions, masses, network.Springs, pinned);
        }
    }
}
