using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>How the composite shades a fluid pixel.</summary>
    public enum FluidLookModel
    {
        /// <summary>Refraction, Beer–Lambert absorption, Schlick Fresnel reflection of the sky, specular, optional emission.</summary>
        Lit = 0,
        /// <summary>Unlit: one colour at a fixed opacity.</summary>
        Flat = 1,
        /// <summary>Unlit: the colour's opacity grows with thickness, 1 − e^(−k·t).</summary>
        ThicknessTinted = 2,
        /// <summary>Unlit: the colour in a few bands of n·l, with a darker outline at the silhouette.</summary>
        Toon = 3,
    }

    /// <summary>
    /// The parameters of one fluid look (linear RGB colours). Lit looks use all but the toon fields; unlit looks use
    /// <see cref="Colour"/>, <see cref="Opacity"/>, <see cref="Absorption"/> (thickness-tinted) and the toon fields.
    /// </summary>
    [Serializable]
    public struct FluidLook
    {
        public FluidLookModel Model;
        /// <summary>Body colour (linear RGB, 0–1): what thick fluid scatters back (lit), or the unlit colour.</summary>
        public float3 Colour;
        /// <summary>Beer–Lambert absorption per colour channel (1/m): transmitted light falls as e^(−a·t) over thickness t.</summary>
        public float3 Absorption;
        /// <summary>Share of the absorbed light replaced by <see cref="Colour"/> (0 clear and dark, 1 milky).</summary>
        public float Scattering;
        /// <summary>Index of refraction (1–3): sets the Fresnel reflectance at normal incidence, F0 = ((n − 1)/(n + 1))².</summary>
        public float IndexOfRefraction;
        /// <summary>
        /// Refraction: the background shifts by this times the thickness times the normal's screen tilt (dimensionless;
        /// a slab refracts by about 1 − 1/n, so 0.25 for water). 0 turns refraction off.
        /// </summary>
        public float Refraction;
        /// <summary>Blinn–Phong exponent of the light's highlight (1–4096).</summary>
        public float SpecularPower;
        /// <summary>Highlight intensity (0–10).</summary>
        public float Specular;
        /// <summary>Emitted colour at full heat (linear RGB, HDR, may exceed 1).</summary>
        public float3 Emission;
        /// <summary>Attribute (temperature, K) at and below which the fluid emits nothing.</summary>
        public float ColdAttribute;
        /// <summary>Attribute (temperature, K) at and above which it emits <see cref="Emission"/> in full.</summary>
        public float HotAttribute;
        /// <summary>Unlit opacity (0–1).</summary>
        public float Opacity;
        /// <summary>Toon: bands of n·l (1–8).</summary>
        public int Bands;
        /// <summary>Toon: outline colour (linear RGB).</summary>
        public float3 OutlineColour;
        /// <summary>Toon: the outline covers pixels whose normal faces away from the viewer by more than this (n·v below it, 0–1).</summary>
        public float Outline;

        static FluidLook Clear(float3 absorption, float ior) => new FluidLook
        {
            Model = FluidLookModel.Lit,
            Colour = new float3(0f),
            Absorption = absorption,
            Scattering = 0f,
            IndexOfRefraction = ior,
            Refraction = 0.25f,
            SpecularPower = 400f,
            Specular = 1.5f,
            Emission = float3.zero,
            ColdAttribute = 0f,
            HotAttribute = 1f,
            Opacity = 1f,
            Bands = 3,
            OutlineColour = float3.zero,
            Outline = 0.25f,
        };

        /// <summary>Clear water, tinted blue-green when deep (scaled up from water's 0.45 / 0.06 / 0.02 per metre so a tabletop pool shows it).</summary>
        public static FluidLook Water => Clear(new float3(22f, 6f, 3.5f), 1.33f);

        /// <summary>Amber, absorbing blue strongly, a little milky.</summary>
        public static FluidLook Honey
        {
            get
            {
                FluidLook l = Clear(new float3(6f, 30f, 140f), 1.5f);
                l.Colour = new float3(0.6f, 0.28f, 0.03f);
                l.Scattering = 0.35f;
                l.Refraction = 0.3f;
                l.SpecularPower = 200f;
                return l;
            }
        }

        /// <summary>Green and milky.</summary>
        public static FluidLook Slime
        {
            get
            {
                FluidLook l = Clear(new float3(70f, 12f, 80f), 1.4f);
                l.Colour = new float3(0.18f, 0.75f, 0.08f);
                l.Scattering = 0.75f;
                l.Refraction = 0.15f;
                l.SpecularPower = 80f;
                return l;
            }
        }

        /// <summary>Dark, nearly opaque, very glossy.</summary>
        public static FluidLook Oil
        {
            get
            {
                FluidLook l = Clear(new float3(160f, 170f, 190f), 1.47f);
                l.Colour = new float3(0.04f, 0.03f, 0.015f);
                l.Scattering = 0.15f;
                l.Refraction = 0.1f;
                l.SpecularPower = 1200f;
                l.Specular = 3f;
                return l;
            }
        }

        /// <summary>Opaque crust that glows orange above 900 K and white-yellow at 1400 K (the particle attribute is its temperature).</summary>
        public static FluidLook Lava
        {
            get
            {
                FluidLook l = Clear(new float3(400f), 1.6f);
                l.Colour = new float3(0.07f, 0.035f, 0.025f);
                l.Scattering = 1f;
                l.Refraction = 0f;
                l.SpecularPower = 40f;
                l.Specular = 0.4f;
                l.Emission = new float3(6f, 1.6f, 0.25f);
                l.ColdAttribute = 900f;
                l.HotAttribute = 1400f;
                return l;
            }
        }

        /// <summary>Unlit: one blue at 85 % opacity.</summary>
        public static FluidLook FlatColour => Unlit(FluidLookModel.Flat, new float3(0.1f, 0.45f, 0.9f));

        /// <summary>Unlit: blue whose opacity follows thickness (k = 40 /m).</summary>
        public static FluidLook ThicknessTint => Unlit(FluidLookModel.ThicknessTinted, new float3(0.05f, 0.35f, 0.85f));

        /// <summary>Unlit: three bands of light blue with a dark blue outline.</summary>
        public static FluidLook Toon => Unlit(FluidLookModel.Toon, new float3(0.25f, 0.65f, 1f));

        static FluidLook Unlit(FluidLookModel model, float3 colour)
        {
            FluidLook l = Clear(new float3(40f), 1.33f);
            l.Model = model;
            l.Colour = colour;
            l.Opacity = 0.85f;
            l.Refraction = 0f;
            l.OutlineColour = new float3(0.02f, 0.06f, 0.2f);
            return l;
        }

        /// <summary>Every preset with its name, in gallery order.</summary>
        public static (string Name, FluidLook Look)[] Presets => new[]
        {
            ("water", Water), ("honey", Honey), ("slime", Slime), ("oil", Oil), ("lava", Lava),
            ("flat", FlatColour), ("thickness-tint", ThicknessTint), ("toon", Toon),
        };

        /// <summary>Fresnel reflectance at normal incidence, ((n − 1)/(n + 1))².</summary>
        public float F0 => (IndexOfRefraction - 1f) / (IndexOfRefraction + 1f) * ((IndexOfRefraction - 1f) / (IndexOfRefraction + 1f));

        /// <summary>A copy with every unusable value replaced (non-finite, negative, out of range); <paramref name="problems"/> names each.</summary>
        public FluidLook Sanitized(out string problems)
        {
            System.Text.StringBuilder sb = null; // allocated only when something is replaced
            FluidLook l = this;
            FluidLook d = Water;
            if (!Enum.IsDefined(typeof(FluidLookModel), l.Model)) { Note(ref sb).Append($"unknown look model {(int)l.Model}: lit used. "); l.Model = FluidLookModel.Lit; }
            l.Colour = Colour3(l.Colour, 0f, 1f, "colour", d.Colour, ref sb);
            l.Absorption = Colour3(l.Absorption, 0f, 1e5f, "absorption (1/m)", d.Absorption, ref sb);
            l.Emission = Colour3(l.Emission, 0f, 1e4f, "emission", float3.zero, ref sb);
            l.OutlineColour = Colour3(l.OutlineColour, 0f, 1f, "outline colour", float3.zero, ref sb);
            l.Scattering = Scalar(l.Scattering, 0f, 1f, "scattering", d.Scattering, ref sb);
            l.IndexOfRefraction = Scalar(l.IndexOfRefraction, 1f, 3f, "index of refraction", d.IndexOfRefraction, ref sb);
            l.Refraction = Scalar(l.Refraction, 0f, 10f, "refraction", d.Refraction, ref sb);
            l.SpecularPower = Scalar(l.SpecularPower, 1f, 4096f, "specular power", d.SpecularPower, ref sb);
            l.Specular = Scalar(l.Specular, 0f, 10f, "specular", d.Specular, ref sb);
            l.Opacity = Scalar(l.Opacity, 0f, 1f, "opacity", d.Opacity, ref sb);
            l.Outline = Scalar(l.Outline, 0f, 1f, "outline", d.Outline, ref sb);
            if (l.Bands < 1 || l.Bands > 8) { Note(ref sb).Append($"{l.Bands} toon bands is outside 1–8: 3 used. "); l.Bands = 3; }
            if (!math.isfinite(l.ColdAttribute) || !math.isfinite(l.HotAttribute) || !(l.HotAttribute > l.ColdAttribute))
            {
                Note(ref sb).Append($"hot attribute {l.HotAttribute} must be finite and above the cold one {l.ColdAttribute}: emission off. ");
                l.ColdAttribute = 0f;
                l.HotAttribute = 1f;
                l.Emission = float3.zero;
            }
            problems = sb == null ? string.Empty : sb.ToString().TrimEnd();
            return l;
        }

        static float Scalar(float v, float lo, float hi, string name, float fallback, ref System.Text.StringBuilder sb)
        {
            if (math.isfinite(v) && v >= lo && v <= hi)
                return v;
            Note(ref sb).Append($"{name} {v} is outside {lo}–{hi}: {fallback} used. ");
            return fallback;
        }

        static float3 Colour3(float3 v, float lo, float hi, string name, float3 fallback, ref System.Text.StringBuilder sb)
        {
            if (math.all(math.isfinite(v)) && math.all(v >= lo) && math.all(v <= hi))
                return v;
            Note(ref sb).Append($"{name} ({v.x}, {v.y}, {v.z}) has a value outside {lo}–{hi}: ({fallback.x}, {fallback.y}, {fallback.z}) used. ");
            return fallback;
        }

        static System.Text.StringBuilder Note(ref System.Text.StringBuilder sb) => sb ??= new System.Text.StringBuilder();
    }
}
