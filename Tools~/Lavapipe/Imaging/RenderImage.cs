using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Lavapipe.Imaging
{
    /// <summary>Linear-light images (row 0 at the bottom) to sRGB bytes and back, and a perceptual difference (CIE76 ΔE in L*a*b*).</summary>
    public static class RenderImage
    {
        /// <summary>
        /// The fluid's colour (<paramref name="fw"/> × <paramref name="fh"/>, premultiplied by its coverage) over the scene
        /// (<paramref name="w"/> × <paramref name="h"/>), row 0 at the bottom: what Unity's overlay pass does, sampling the
        /// fluid bilinearly with clamping (one texel per pixel when the sizes match).
        /// </summary>
        public static float4[] Over(ReadOnlySpan<float4> fluid, int fw, int fh, ReadOnlySpan<float4> scene, int w, int h)
        {
            var result = new float4[scene.Length];
            for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++)
                {
                    float tx = (x + 0.5f) * fw / w - 0.5f, ty = (y + 0.5f) * fh / h - 0.5f;
                    int bx = (int)Math.Floor(tx), by = (int)Math.Floor(ty);
                    float ax = tx - bx, ay = ty - by;
                    float4 f = (At(fluid, fw, fh, bx, by) * (1f - ax) + At(fluid, fw, fh, bx + 1, by) * ax) * (1f - ay)
                        + (At(fluid, fw, fh, bx, by + 1) * (1f - ax) + At(fluid, fw, fh, bx + 1, by + 1) * ax) * ay;
                    float4 s = scene[y * w + x];
                    result[y * w + x] = new float4(f.xyz + s.xyz * (1f - f.w), 1f);
                }
            return result;
        }

        static float4 At(ReadOnlySpan<float4> image, int w, int h, int x, int y) => image[Math.Clamp(y, 0, h - 1) * w + Math.Clamp(x, 0, w - 1)];

        /// <summary>sRGB transfer function (IEC 61966-2-1) of a linear value, clamped to [0, 1].</summary>
        public static byte ToSrgb(float linear)
        {
            double v = Math.Clamp(linear, 0f, 1f);
            double s = v <= 0.0031308 ? 12.92 * v : 1.055 * Math.Pow(v, 1 / 2.4) - 0.055;
            return (byte)Math.Round(s * 255.0);
        }

        /// <summary>RGBA bytes, top row first (PNG order), from linear colours with row 0 at the bottom.</summary>
        public static byte[] ToRgba(ReadOnlySpan<float4> linear, int width, int height)
        {
            var bytes = new byte[width * height * 4];
            for (int y = 0; y < height; y++)
                for (int x = 0; x < width; x++)
                {
                    float4 c = linear[(height - 1 - y) * width + x];
                    int o = (y * width + x) * 4;
                    bytes[o] = ToSrgb(c.x);
                    bytes[o + 1] = ToSrgb(c.y);
                    bytes[o + 2] = ToSrgb(c.z);
                    bytes[o + 3] = 255;
                }
            return bytes;
        }

        /// <summary>A grey ramp of a scalar field (row 0 at the bottom): 0 → black at <paramref name="lo"/>, white at <paramref name="hi"/>, empty (≤ 0) dark blue.</summary>
        public static float4[] Ramp(ReadOnlySpan<float> values, float lo, float hi)
        {
            var c = new float4[values.Length];
            for (int i = 0; i < values.Length; i++)
            {
                float t = values[i] > 0f ? math.saturate((values[i] - lo) / (hi - lo)) : -1f;
                c[i] = t < 0f ? new float4(0.02f, 0.02f, 0.06f, 1f) : new float4(t, t, t, 1f);
            }
            return c;
        }

        static double Linear(byte srgb)
        {
            double s = srgb / 255.0;
            return s <= 0.04045 ? s / 12.92 : Math.Pow((s + 0.055) / 1.055, 2.4);
        }

        /// <summary>CIE L*a*b* (D65) of an sRGB pixel.</summary>
        public static (double L, double A, double B) Lab(byte r, byte g, byte b)
        {
            double lr = Linear(r), lg = Linear(g), lb = Linear(b);
            double x = (0.4124 * lr + 0.3576 * lg + 0.1805 * lb) / 0.95047;
            double y = 0.2126 * lr + 0.7152 * lg + 0.0722 * lb;
            double z = (0.0193 * lr + 0.1192 * lg + 0.9505 * lb) / 1.08883;
            static double F(double t) => t > 216.0 / 24389.0 ? Math.Cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
            double fx = F(x), fy = F(y), fz = F(z);
            return (116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz));
        }

        /// <summary>Per-pixel CIE76 ΔE between two RGBA images of the same size.</summary>
        public static double[] DeltaE(byte[] a, byte[] b)
        {
            if (a.Length != b.Length)
                throw new ArgumentException("images differ in size");
            var d = new double[a.Length / 4];
            for (int i = 0; i < d.Length; i++)
            {
                var p = Lab(a[4 * i], a[4 * i + 1], a[4 * i + 2]);
                var q = Lab(b[4 * i], b[4 * i + 1], b[4 * i + 2]);
                d[i] = Math.Sqrt((p.L - q.L) * (p.L - q.L) + (p.A - q.A) * (p.A - q.A) + (p.B - q.B) * (p.B - q.B));
            }
            return d;
        }
    }
}
