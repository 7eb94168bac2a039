using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>One method of the study with its cost knob: a family (legend entry), the knob values to sweep and how to build a body.</summary>
    public sealed class MethodVariant
    {
        /// <summary>Legend entry, e.g. "FEM co-rotational, implicit".</summary>
        public readonly string Family;
        /// <summary>What the knob counts, e.g. "substeps".</summary>
        public readonly string KnobUnit;
        /// <summary>Knob values of the full run, cheapest first.</summary>
        public readonly int[] Knobs;
        /// <summary>Knob values of the quick run (empty = the method is left out of the quick run).</summary>
        public readonly int[] QuickKnobs;
        /// <summary>
        /// Resolutions swept (cells across the body's thinnest side; the scene sets the others from it), each with every
        /// knob value; empty = the scene's default resolution only.
        /// </summary>
        public readonly int[] Resolutions;
        /// <summary>Finest resolution of the default run (cells across); 0 = every resolution of <see cref="Resolutions"/>.</summary>
        public readonly int StandardMaxResolution;
        /// <summary>Builds a body of the setup with a knob value; the cell size (m) sizes shape matching's clusters.</summary>
        public readonly Func<MethodBodySetup, int, float, IMethodBody> Create;
        /// <summary>Particles of a body of the setup (the mesh's nodes unless the method adds its own, as quadratic elements do).</summary>
        public readonly Func<MethodBodySetup, int> ParticleCount;
        /// <summary>Knob values of the default run (a subset of <see cref="Knobs"/>; empty = the method runs in --full only).</summary>
        public readonly int[] StandardKnobs;

        public MethodVariant(string family, string knobUnit, int[] knobs, int[] quickKnobs, Func<MethodBodySetup, int, float, IMethodBody> create,
            int[] resolutions = null, int standardMaxResolution = 0, Func<MethodBodySetup, int> particleCount = null, int[] standardKnobs = null)
        {
            StandardKnobs = standardKnobs ?? knobs;
            ParticleCount = particleCount ?? (s => s.Mesh.NodeCount);
            StandardMaxResolution = standardMaxResolution;
            Family = family;
            KnobUnit = knobUnit;
            Knobs = knobs;
            QuickKnobs = quickKnobs;
            Create = create;
            Resolutions = resolutions ?? new int[0];
        }

        /// <summary>
        /// Resolutions a run of <paramref name="scope"/> sweeps, none finer than <paramref name="maxResolution"/> nor, in the default
        /// run, <paramref name="standardMaxResolution"/> (0 = no cap); {0} (the scene's default) when the variant sweeps none or the run is quick.
        /// The default run thins a sweep of more than three resolutions to every other one from the coarsest, and the finest.
        /// </summary>
        public int[] ResolutionsOf(RunScope scope, int maxResolution, int standardMaxResolution)
        {
            if (Resolutions.Length == 0 || scope == RunScope.Quick)
                return new[] { 0 };
            int cap = scope == RunScope.Standard && standardMaxResolution > 0 ? Math.Min(maxResolution, standardMaxResolution) : maxResolution;
            int[] swept = Array.FindAll(Resolutions, n => n <= cap);
            if (scope != RunScope.Standard || swept.Length <= 3)
                return swept;
            var thinned = new System.Collections.Generic.List<int>();
            for (int k = 0; k < swept.Length; k += 2)
                thinned.Add(swept[k]);
            if (swept.Length % 2 == 0)
                thinned.Add(swept[swept.Length - 1]);
            return thinned.ToArray();
        }

        /// <summary>"family; knob unit", the scenario's method text (the figure splits it at the semicolon before the knob).</summary>
        public string Label(int knob) => $"{Family}; {knob} {KnobUnit}";

        /// <summary>"family; knob unit, n across" for a swept resolution (0 = the scene's default: no suffix).</summary>
        public string Label(int knob, int resolution) => resolution > 0 ? $"{Label(knob)}, {resolution} across" : Label(knob);
    }
}
