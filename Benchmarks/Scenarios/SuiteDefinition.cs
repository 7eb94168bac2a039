namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// What a suite measures, as the report prints it: one sentence above the table, then under it a short list (body,
    /// material, load, reference, metric). Each entry is a line or two; the manual page in <see cref="Details"/> holds the rest.
    /// </summary>
    public sealed class SuiteDefinition
    {
        /// <summary>One sentence: the question the table answers.</summary>
        public string Purpose = "";
        /// <summary>The body or scene simulated (geometry, resolution, particles).</summary>
        public string Body = "";
        /// <summary>Its material or solver settings.</summary>
        public string Material = "";
        /// <summary>What drives it (gravity, a release, an imposed step) and for how long.</summary>
        public string Load = "";
        /// <summary>What the answer is compared with; "none" for a pure cost measurement.</summary>
        public string Reference = "";
        /// <summary>The metrics of the table and the cost column: what one item is, how errors are formed.</summary>
        public string Metric = "";
        /// <summary>Further short entries (each one line), or null.</summary>
        public string[] Notes;
        /// <summary>Manual page (path under Documentation~, with an optional #anchor) that describes the suite in full, or null.</summary>
        public string Details;
    }
}
