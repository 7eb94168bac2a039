using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One material preset on the frame-rate suite's body, shared by its rows: a <see cref="Edge"/>³ lattice cube of
    /// <see cref="BodySize"/> m with overlapping 4³ clusters, the preset's parameters (default substep phase limit, particle
    /// radius half the spacing), its <see cref="FullyResistedMode"/> and its dt → 0 resting state, computed once.
    /// </summary>
    public sealed class FrameRateStudy
    {
        /// <summary>Particles per edge.</summary>
        public const int Edge = 6;
        /// <summary>Side of the body (m).</summary>
        public const float BodySize = 0.5f;

        public readonly string Preset;
        public readonly ShapeMatchingMaterial Material;
        public readonly ShapeMatchingModelData Model;
        /// <summary>The preset applied to the default parameters; the rows set the substeps.</summary>
        public readonly ShapeMatchingParameters Parameters;
        /// <summary>Pattern of the fully resisted mode (linear goals on overlapping clusters have one).</summary>
        public readonly double[] ResistedMode;
        RestingSagReference? m_Reference;
        /// <summary>Guards <see cref="Reference"/>: scenarios of one study may be evaluated on different threads.</summary>
        readonly object m_Lock = new object();

        static readonly Dictionary<string, FrameRateStudy> s_Studies = new Dictionary<string, FrameRateStudy>();

        /// <summary>The shared study of a preset ("Jelly", "Rubber", "Clay", or "Clay (elastic)": Clay without plasticity).</summary>
        public static FrameRateStudy For(string preset)
        {
            lock (s_Studies)
            {
                if (!s_Studies.TryGetValue(preset, out FrameRateStudy study))
                    s_Studies[preset] = study = new FrameRateStudy(preset);
                return study;
            }
        }

        /// <summary>The material of a preset name.</summary>
        public static ShapeMatchingMaterial MaterialOf(string preset)
        {
            switch (preset)
            {
                case "Jelly": return ShapeMatchingMaterial.Jelly;
                case "Rubber": return ShapeMatchingMaterial.Rubber;
                case "Clay": return ShapeMatchingMaterial.Clay;
                case "Clay (elastic)":
                    ShapeMatchingMaterial clay = ShapeMatchingMaterial.Clay;
                    clay.Plasticity = PlasticityParameters.None;
                    return clay;
                default: throw new System.ArgumentException($"unknown preset '{preset}'", nameof(preset));
            }
        }

        public FrameRateStudy(string preset)
        {
            Preset = preset;
            Material = MaterialOf(preset);
            Model = ShapeMatchingBenchmarkBody.Lattice(Edge, BodySize, ShapeMatchingClusterLayout.Overlapping, Material.Mode);
            ShapeMatchingParameters p = Material.ApplyTo(ShapeMatchingParameters.Default);
            p.Body.ParticleRadius = ShapeMatchingBenchmarkBody.ParticleRadius(Edge, BodySize);
            Parameters = p;
            ResistedMode = FullyResistedMode.Find(Model, Material.Mode);
        }

        /// <summary>The dt → 0 resting state (<see cref="RestingSag.Extrapolate"/>).</summary>
        public RestingSagReference Reference
        {
            get
            {
                lock (m_Lock)
                {
                    if (m_Reference == null)
                        m_Reference = RestingSag.Extrapolate(Model, Parameters);
                    return m_Reference.Value;
                }
            }
        }

        /// <summary>The parameters with <paramref name="substeps"/> requested.</summary>
        public ShapeMatchingParameters WithSubsteps(int substeps)
        {
            ShapeMatchingParameters p = Parameters;
            p.Body.Substeps = substeps;
            return p;
        }
    }
}
