using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The constants of the surface kernels (the float4 / uint4 globals of FluidSurfaceCommon.hlsl), computed on the CPU
    /// from a camera, the settings, the look and the lighting, and uploaded through <see cref="Set"/>; <see cref="Names"/>
    /// gives the shader name of each global index.
    /// </summary>
    public struct FluidSurfaceConstants
    {
        public float4 ViewRow0, ViewRow1, ViewRow2, DepthPinhole, ThicknessPinhole, ScreenPinhole;
        public int4 DepthSize, OtherSizes, SurfaceCounts, Composite;
        public float4 SceneDepthParams, Splat, AttributeRange, Filter;
        public float4 LookColour, LookAbsorption, LookEmission, LookSurface, LookOutline;
        public float4 LightDirection, LightColour, SkyZenith, SkyHorizon, ViewUp;

        /// <summary>Particles drawn this frame.</summary>
        public int ParticleCount => SurfaceCounts.x;
        /// <summary>Tile entries that fit; more are dropped (counted in <see cref="FluidSurfaceLayout.StatDropped"/>).</summary>
        public int TileCapacity => SurfaceCounts.y;
        /// <summary>The targets the composite reads besides depth (<see cref="FluidSurfacePassList.Flags"/>).</summary>
        public int PassFlags => SurfaceCounts.w;

        /// <summary>Thickness quantum: chords are summed as integers of r / 1024 metres.</summary>
        public const float QuantaPerRadius = 1024f;

        /// <summary>
        /// The constants for <paramref name="particles"/> particles drawn by <paramref name="camera"/>, with room for
        /// <paramref name="tileCapacity"/> tile entries, and the pass flags of <see cref="FluidSurfacePassList.Of"/>. <paramref name="sceneDepthParams"/> is Unity's _ZBufferParams
        /// for the camera depth texture (unused by the buffer harness, whose scene depth is already eye depth);
        /// <paramref name="flipY"/> when texture row 0 is the top of the screen.
        /// </summary>
        public static FluidSurfaceConstants Of(in FluidSurfaceCamera camera, in FluidSurfaceSettings settings, in FluidLook look,
            in FluidSurfaceLighting lighting, int particles, int tileCapacity, float4 sceneDepthParams = default, bool flipY = false)
        {
            FluidSurfaceTargets t = FluidSurfaceTargets.Of(camera, settings);
            float3x3 rotation = camera.Rotation;
            float3x3 rows = math.transpose(rotation);
            float r = settings.ParticleRadius;
            int threadSide = settings.DepthDivisor == 1 ? 1 : 2;
            FluidSurfacePassList passes = FluidSurfacePassList.Of(settings, look);
            return new FluidSurfaceConstants
            {
                ViewRow0 = new float4(rows.c0, camera.Translation.x),
                ViewRow1 = new float4(rows.c1, camera.Translation.y),
                ViewRow2 = new float4(rows.c2, camera.Translation.z),
                DepthPinhole = camera.Pinhole(settings.DepthDivisor),
                ThicknessPinhole = camera.Pinhole(FluidSurfaceSettings.ThicknessDivisor),
                ScreenPinhole = camera.Pinhole(1),
                DepthSize = new int4(t.Depth.x, t.Depth.y, t.Tiles.x, t.Tiles.y),
                OtherSizes = new int4(t.Thickness.x, t.Thickness.y, t.Screen.x, t.Screen.y),
                SurfaceCounts = new int4(particles, tileCapacity, threadSide, passes.Flags),
                Composite = new int4(settings.DepthDivisor, (int)look.Model, flipY ? 1 : 0, settings.CompositeDivisor),
                SceneDepthParams = sceneDepthParams,
                Splat = new float4(r, r * r, camera.Near, r / QuantaPerRadius),
                AttributeRange = new float4(look.ColdAttribute, 1f / (look.HotAttribute - look.ColdAttribute), 0f, 0f),
                Filter = new float4(settings.FilterRadius, settings.MaxFilterPixels, settings.DepthRange, settings.CurvatureStep),
                LookColour = new float4(look.Colour, look.Scattering),
                LookAbsorption = new float4(look.Absorption, look.F0),
                LookEmission = new float4(look.Emission, look.Refraction),
                LookSurface = new float4(look.SpecularPower, look.Specular, look.Opacity, look.Bands),
                LookOutline = new float4(look.OutlineColour, look.Outline),
                LightDirection = new float4(math.normalize(math.mul(rotation, lighting.LightDirection)), settings.MaxRefractionPixels),
                LightColour = new float4(lighting.LightColour, 0f),
                SkyZenith = new float4(lighting.SkyZenith, 0f),
                SkyHorizon = new float4(lighting.SkyHorizon, 0f),
                ViewUp = new float4(math.normalize(math.mul(rotation, lighting.Up)), 0f),
            };
        }

        /// <summary>Unity's _ZBufferParams for a camera depth texture: eye depth = 1 / (z·d + w).</summary>
        public static float4 ZBufferParams(float near, float far, bool reversedZ)
        {
            float x = reversedZ ? -1f + far / near : 1f - far / near;
            float y = reversedZ ? 1f : far / near;
            return new float4(x, y, x / far, y / far);
        }

        /// <summary>The names of the globals, in the order of <see cref="Value"/>.</summary>
        public static readonly string[] Names =
        {
            "_ViewRow0", "_ViewRow1", "_ViewRow2", "_DepthPinhole", "_ThicknessPinhole", "_ScreenPinhole",
            "_DepthSize", "_OtherSizes", "_SurfaceCounts", "_Composite",
            "_SceneDepthParams", "_Splat", "_AttributeRange", "_Filter",
            "_LookColour", "_LookAbsorption", "_LookEmission", "_LookSurface", "_LookOutline",
            "_LightDirection", "_LightColour", "_SkyZenith", "_SkyHorizon", "_ViewUp",
        };

        /// <summary>Whether global <paramref name="i"/> is a uint4.</summary>
        public static bool IsInteger(int i) => i >= 6 && i <= 9;

        /// <summary>Sets every global on <paramref name="commands"/>: float4s as vectors, uint4s as int4 bits.</summary>
        public void Set<T>(ref T commands) where T : IFluidSurfaceCommands
        {
            for (int i = 0; i < Names.Length; i++)
            {
                if (IsInteger(i))
                    commands.SetInts(i, Integer(i));
                else
                    commands.SetVector(i, Value(i));
            }
        }

        /// <summary>Global <paramref name="i"/> of <see cref="Names"/> (a float4 one).</summary>
        float4 Value(int i) => i switch
        {
            0 => ViewRow0, 1 => ViewRow1, 2 => ViewRow2, 3 => DepthPinhole, 4 => ThicknessPinhole, 5 => ScreenPinhole,
            10 => SceneDepthParams, 11 => Splat, 12 => AttributeRange, 13 => Filter,
            14 => LookColour, 15 => LookAbsorption, 16 => LookEmission, 17 => LookSurface, 18 => LookOutline,
            19 => LightDirection, 20 => LightColour, 21 => SkyZenith, 22 => SkyHorizon, _ => ViewUp,
        };

        /// <summary>Global <paramref name="i"/> as a uint4 (only where <see cref="IsInteger"/>).</summary>
        int4 Integer(int i) => i switch { 6 => DepthSize, 7 => OtherSizes, 8 => SurfaceCounts, _ => Composite };
    }
}
