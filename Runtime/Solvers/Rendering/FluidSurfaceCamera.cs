using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// A perspective camera as the fluid surface passes see it: Unity's view space (right-handed, the camera looks down
    /// −z, so eye depth is −z), pixel centres at i + 0.5 with row 0 at the bottom of the screen.
    /// </summary>
    public struct FluidSurfaceCamera
    {
        /// <summary>World → view rotation (the upper 3 × 3 of Unity's <c>Camera.worldToCameraMatrix</c>).</summary>
        public float3x3 Rotation;
        /// <summary>World → view translation (m; the matrix's last column).</summary>
        public float3 Translation;
        /// <summary>Width and height of the full-resolution target (pixels).</summary>
        public int Width, Height;
        /// <summary>Vertical field of view (degrees).</summary>
        public float FieldOfView;
        /// <summary>Near clip distance (m): spheres reaching closer than this are not drawn.</summary>
        public float Near;

        /// <summary>A camera at <paramref name="eye"/> looking at <paramref name="target"/> with +y up.</summary>
        public static FluidSurfaceCamera LookAt(float3 eye, float3 target, int width, int height, float fieldOfView, float near = 0.01f)
        {
            float3 forward = math.normalize(target - eye);
            float3 right = math.normalize(math.cross(forward, new float3(0f, 1f, 0f)));
            float3 up = math.cross(right, forward);
            // Rows: right, up, −forward (view z points back at the viewer).
            float3x3 r = math.transpose(new float3x3(right, up, -forward));
            return new FluidSurfaceCamera
            {
                Rotation = r,
                Translation = -math.mul(r, eye),
                Width = width,
                Height = height,
                FieldOfView = fieldOfView,
                Near = near,
            };
        }

        /// <summary>
        /// The pinhole of a target <paramref name="divisor"/> times coarser than the screen (1 full, 2 half resolution):
        /// x focal length, y focal length (pixels; f = H / (2 tan(fov/2)) / divisor), zw principal point (pixels). A view
        /// point (x, y, −z) lands on pixel (c_x + f x / z, c_y + f y / z).
        /// </summary>
        public float4 Pinhole(int divisor)
        {
            float half = FieldOfView * (math.PI / 360f);
            float f = Height / (2f * (math.sin(half) / math.cos(half))) / divisor;
            return new float4(f, f, 0.5f * Width / divisor, 0.5f * Height / divisor);
        }

        /// <summary>Pixels of a target <paramref name="divisor"/> times coarser than the screen, rounded up.</summary>
        public int2 Size(int divisor) => new int2((Width + divisor - 1) / divisor, (Height + divisor - 1) / divisor);

        public float3 ToView(float3 world) => math.mul(Rotation, world) + Translation;
    }
}
