using System.Runtime.InteropServices;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The constants of the surface kernels, computed on the CPU from a camera, the settings, the look and the lighting,
    /// and uploaded whole as the kernels' constant buffer (<see cref="IFluidSurfaceCommands.SetConstants"/>): the C# side
    /// of <c>Shaders/Kernels/FluidSurfaceConstants.hlsl</c>, with the same fields in the same order at the same byte
    /// offsets (HLSL constant-buffer packing: 16-byte rows, a float3 starts a row and a scalar closes it). The C#
    /// reference passes read the same struct.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FluidSurfaceConstants
    {
        /// <summary>Bytes of the constant buffer: a multiple of 16, as constant buffers require.</summary>
        public const int Bytes = 352;
        /// <summary>The constant buffer's name in HLSL (its shader property).</summary>
        public const string BufferName = "FluidSurfaceConstants";
        /// <summary>Thickness quantum: chords are summed as integers of r / 1024 metres.</summary>
        public const float QuantaPerRadius = 1024f;

        /// <summary>World → view, rows 0..2: xyz rotation, w translation (m).</summary>
        public float4 ViewRow0, ViewRow1, ViewRow2;
        /// <summary>Focal length x, y of the depth target (pixels).</summary>
        public float2 DepthFocal;
        /// <summary>Principal point x, y of the depth target (pixels).</summary>
        public float2 DepthCentre;
        public float2 ThicknessFocal, ThicknessCentre;
        /// <summary>Focal length and principal point of the full-resolution screen.</summary>
        public float2 ScreenFocal, ScreenCentre;
        /// <summary>Depth target (pixels).</summary>
        public uint DepthWidth, DepthHeight;
        /// <summary>Tiles of the depth target along x, y.</summary>
        public uint TilesX, TilesY;
        /// <summary>Thickness target (pixels).</summary>
        public uint ThicknessWidth, ThicknessHeight;
        /// <summary>Screen (pixels).</summary>
        public uint ScreenWidth, ScreenHeight;
        /// <summary>Particles drawn this frame.</summary>
        public uint ParticleCount;
        /// <summary>Tile entries that fit; more are dropped (counted in <see cref="FluidSurfaceLayout.StatDropped"/>).</summary>
        public uint TileCapacity;
        /// <summary>Thickness pixels per thread side in a tile (1 or 2).</summary>
        public uint ThicknessPixelsPerThread;
        /// <summary>The targets the composite reads besides depth (<see cref="FluidSurfacePassList.Flags"/>).</summary>
        public uint PassFlags;
        /// <summary>Depth target resolution: 1 full, 2 half.</summary>
        public uint DepthDivisor;
        /// <summary><see cref="FluidLookModel"/> of the look.</summary>
        public uint LookModel;
        /// <summary>1 when texture row 0 is the top of the screen.</summary>
        public uint FlipY;
        /// <summary>Composite resolution: 1 full, 2 half.</summary>
        public uint CompositeDivisor;
        /// <summary>Particle radius r (m).</summary>
        public float ParticleRadius;
        /// <summary>r² (m²).</summary>
        public float ParticleRadiusSquared;
        /// <summary>Near clip distance (m).</summary>
        public float NearPlane;
        /// <summary>Metres per unit of summed chord: r / <see cref="QuantaPerRadius"/>.</summary>
        public float ThicknessQuantum;
        /// <summary>World radius of the smoothing (m).</summary>
        public float FilterRadius;
        /// <summary>Largest smoothing radius (pixels).</summary>
        public float MaxFilterPixels;
        /// <summary>μ: neighbours farther in depth belong to another surface (m).</summary>
        public float DepthRange;
        /// <summary>λ of the curvature flow.</summary>
        public float CurvatureStep;
        /// <summary>The look's colour (linear rgb).</summary>
        public float3 BodyColour;
        /// <summary>Share of the absorbed light replaced by the lit body colour.</summary>
        public float Scattering;
        /// <summary>Beer–Lambert absorption per channel (1/m).</summary>
        public float3 Absorption;
        /// <summary>Schlick's F0.</summary>
        public float FresnelF0;
        /// <summary>Emission at full heat (linear rgb).</summary>
        public float3 Emission;
        /// <summary>Background shift per metre of thickness.</summary>
        public float Refraction;
        /// <summary>Blinn–Phong exponent.</summary>
        public float SpecularPower;
        /// <summary>Highlight strength.</summary>
        public float Specular;
        /// <summary>Unlit looks' opacity.</summary>
        public float Opacity;
        /// <summary>Toon look's bands of n·l.</summary>
        public float ToonBands;
        /// <summary>Toon look's outline (linear rgb).</summary>
        public float3 OutlineColour;
        /// <summary>Outline where n·v is below this.</summary>
        public float OutlineThreshold;
        /// <summary>Unit vector toward the light (view space).</summary>
        public float3 LightDirection;
        /// <summary>Largest background shift (pixels).</summary>
        public float MaxRefractionPixels;
        /// <summary>Light colour (linear rgb).</summary>
        public float3 LightColour;
        /// <summary>The attribute (temperature, K) that maps to heat 0.</summary>
        public float ColdAttribute;
        /// <summary>Sky straight up (linear rgb).</summary>
        public float3 SkyZenith;
        /// <summary>1 / (hot − cold attribute): heat = (attribute − cold) · this.</summary>
        public float InverseAttributeSpan;
        /// <summary>Sky at the horizon (linear rgb).</summary>
        public float3 SkyHorizon;
        /// <summary>Eye depth = 1 / (SceneDepthScale · device depth + <see cref="SceneDepthOffset"/>): Unity's _ZBufferParams.z.</summary>
        public float SceneDepthScale;
        /// <summary>World up in view space.</summary>
        public float3 ViewUp;
        /// <summary>Unity's _ZBufferParams.w (<see cref="SceneDepthScale"/>).</summary>
        public float SceneDepthOffset;

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
            // Each pinhole: xy focal length, zw principal point.
            float4 depth = camera.Pinhole(settings.DepthDivisor);
            float4 thickness = camera.Pinhole(FluidSurfaceSettings.ThicknessDivisor);
            float4 screen = camera.Pinhole(1);
            return new FluidSurfaceConstants
            {
                ViewRow0 = new float4(rows.c0, camera.Translation.x),
                ViewRow1 = new float4(rows.c1, camera.Translation.y),
                ViewRow2 = new float4(rows.c2, camera.Translation.z),
                DepthFocal = new float2(depth.x, depth.y),
                DepthCentre = new float2(depth.z, depth.w),
                ThicknessFocal = new float2(thickness.x, thickness.y),
                ThicknessCentre = new float2(thickness.z, thickness.w),
                ScreenFocal = new float2(screen.x, screen.y),
                ScreenCentre = new float2(screen.z, screen.w),
                DepthWidth = (uint)t.Depth.x,
                DepthHeight = (uint)t.Depth.y,
                TilesX = (uint)t.Tiles.x,
                TilesY = (uint)t.Tiles.y,
                ThicknessWidth = (uint)t.Thickness.x,
                ThicknessHeight = (uint)t.Thickness.y,
                ScreenWidth = (uint)t.Screen.x,
                ScreenHeight = (uint)t.Screen.y,
                ParticleCount = (uint)particles,
                TileCapacity = (uint)tileCapacity,
                ThicknessPixelsPerThread = (uint)threadSide,
                PassFlags = (uint)passes.Flags,
                DepthDivisor = (uint)settings.DepthDivisor,
                LookModel = (uint)look.Model,
                FlipY = flipY ? 1u : 0u,
                CompositeDivisor = (uint)settings.CompositeDivisor,
                ParticleRadius = r,
                ParticleRadiusSquared = r * r,
                NearPlane = camera.Near,
                ThicknessQuantum = r / QuantaPerRadius,
                FilterRadius = settings.FilterRadius,
                MaxFilterPixels = settings.MaxFilterPixels,
                DepthRange = settings.DepthRange,
                CurvatureStep = settings.CurvatureStep,
                BodyColour = look.Colour,
                Scattering = look.Scattering,
                Absorption = look.Absorption,
                FresnelF0 = look.F0,
                Emission = look.Emission,
                Refraction = look.Refraction,
                SpecularPower = look.SpecularPower,
                Specular = look.Specular,
                Opacity = look.Opacity,
                ToonBands = look.Bands,
                OutlineColour = look.OutlineColour,
                OutlineThreshold = look.Outline,
                LightDirection = math.normalize(math.mul(rotation, lighting.LightDirection)),
                MaxRefractionPixels = settings.MaxRefractionPixels,
                LightColour = lighting.LightColour,
                ColdAttribute = look.ColdAttribute,
                SkyZenith = lighting.SkyZenith,
                InverseAttributeSpan = 1f / (look.HotAttribute - look.ColdAttribute),
                SkyHorizon = lighting.SkyHorizon,
                SceneDepthScale = sceneDepthParams.z,
                ViewUp = math.normalize(math.mul(rotation, lighting.Up)),
                SceneDepthOffset = sceneDepthParams.w,
            };
        }

        /// <summary>Unity's _ZBufferParams for a camera depth texture: eye depth = 1 / (z·d + w).</summary>
        public static float4 ZBufferParams(float near, float far, bool reversedZ)
        {
            float x = reversedZ ? -1f + far / near : 1f - far / near;
            float y = reversedZ ? 1f : far / near;
            return new float4(x, y, x / far, y / far);
        }
    }
}
