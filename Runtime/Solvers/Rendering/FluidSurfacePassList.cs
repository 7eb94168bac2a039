using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>The stages of one fluid's surface frame, in frame order (each row of the documentation's pass table).</summary>
    public enum FluidSurfaceStage
    {
        /// <summary>ClearTiles, CountTiles, ScanTiles, BinParticles.</summary>
        TileLists,
        DepthSplat,
        /// <summary>Optional: only for a look that reads thickness (<see cref="FluidSurfacePassList.ReadsThickness"/>).</summary>
        ThicknessSplat,
        /// <summary>Optional: none with the filter off or zero iterations.</summary>
        Smoothing,
        /// <summary>Optional: only for a look that shades with normals (<see cref="FluidSurfacePassList.ReadsNormals"/>).</summary>
        Normals,
        Composite,
        /// <summary>The raster blend onto the camera colour (not a compute dispatch).</summary>
        Overlay,
    }

    /// <summary>
    /// Which surface passes a frame runs and at what resolution, from the settings and the look: the one list that
    /// <see cref="FluidSurfaceFrame"/> records (URP and lavapipe), <see cref="FluidSurfaceCost"/> counts and
    /// <see cref="FluidSurfaceConstants"/> tells the composite (<see cref="Flags"/>), so a pass that is off is neither
    /// dispatched nor read.
    /// </summary>
    public struct FluidSurfacePassList
    {
        /// <summary>1 full, 2 half resolution (<see cref="FluidSurfaceSettings.DepthDivisor"/>, <see cref="FluidSurfaceSettings.CompositeDivisor"/>).</summary>
        public int DepthDivisor, CompositeDivisor;
        /// <summary>The filter; <see cref="FluidSurfaceFilter.None"/> when the settings run no smoothing pass.</summary>
        public FluidSurfaceFilter Filter;
        /// <summary>Filter iterations; 0 when <see cref="Filter"/> is none.</summary>
        public int Iterations;
        /// <summary>Whether the thickness splat runs and the composite reads thickness.</summary>
        public bool Thickness;
        /// <summary>Whether the normals pass runs and the composite reads normals.</summary>
        public bool Normals;

        /// <summary><see cref="Flags"/> bit: the composite reads the thickness target.</summary>
        public const int ThicknessFlag = 1;
        /// <summary><see cref="Flags"/> bit: the composite reads the normal target.</summary>
        public const int NormalsFlag = 2;
        /// <summary>Dispatches of the tile lists (ClearTiles, CountTiles, ScanTiles, BinParticles).</summary>
        public const int TileListDispatches = 4;

        /// <summary>The passes a frame with these settings and this look runs.</summary>
        public static FluidSurfacePassList Of(in FluidSurfaceSettings settings, in FluidLook look)
        {
            bool smoothing = settings.Filter != FluidSurfaceFilter.None && settings.Iterations > 0;
            return new FluidSurfacePassList
            {
                DepthDivisor = settings.DepthDivisor,
                CompositeDivisor = settings.CompositeDivisor,
                Filter = smoothing ? settings.Filter : FluidSurfaceFilter.None,
                Iterations = smoothing ? settings.Iterations : 0,
                Thickness = ReadsThickness(look),
                Normals = ReadsNormals(look),
            };
        }

        /// <summary>
        /// Whether the look's shading depends on thickness (FluidSurfaceShading.hlsl): thickness-tinted always; lit through
        /// refraction (offset ∝ thickness), absorption (e^(−a·t)) or emission (the mean attribute rides on the thickness
        /// target); flat and toon never.
        /// </summary>
        public static bool ReadsThickness(in FluidLook look) => look.Model switch
        {
            FluidLookModel.ThicknessTinted => true,
            FluidLookModel.Lit => look.Refraction > 0f || math.any(look.Absorption > 0f) || math.any(look.Emission > 0f),
            _ => false,
        };

        /// <summary>Whether the look shades with the normal: lit (Fresnel, light, refraction) and toon (bands, outline); flat and thickness-tinted do not.</summary>
        public static bool ReadsNormals(in FluidLook look) => look.Model == FluidLookModel.Lit || look.Model == FluidLookModel.Toon;

        /// <summary>Smoothing dispatches: one per curvature-flow step, two (x then y) per separable iteration.</summary>
        public int SmoothingPasses => Filter == FluidSurfaceFilter.None ? 0 : Filter == FluidSurfaceFilter.CurvatureFlow ? Iterations : 2 * Iterations;

        /// <summary>The composite's view of the list (_SurfaceCounts.w): <see cref="ThicknessFlag"/> | <see cref="NormalsFlag"/>.</summary>
        public int Flags => (Thickness ? ThicknessFlag : 0) | (Normals ? NormalsFlag : 0);

        /// <summary>Whether the frame runs <paramref name="stage"/>.</summary>
        public bool Has(FluidSurfaceStage stage) => stage switch
        {
            FluidSurfaceStage.ThicknessSplat => Thickness,
            FluidSurfaceStage.Smoothing => SmoothingPasses > 0,
            FluidSurfaceStage.Normals => Normals,
            _ => true,
        };

        /// <summary>Compute dispatches of <paramref name="stage"/> (0 when absent; the overlay is a raster pass).</summary>
        public int Dispatches(FluidSurfaceStage stage) => stage switch
        {
            FluidSurfaceStage.TileLists => TileListDispatches,
            FluidSurfaceStage.Smoothing => SmoothingPasses,
            FluidSurfaceStage.Overlay => 0,
            _ => Has(stage) ? 1 : 0,
        };

        /// <summary>Compute dispatches of the whole frame.</summary>
        public int TotalDispatches
        {
            get
            {
                int n = 0;
                for (var s = FluidSurfaceStage.TileLists; s <= FluidSurfaceStage.Overlay; s++)
                    n += Dispatches(s);
                return n;
            }
        }
    }
}
