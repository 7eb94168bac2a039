// Blends the fluid colour of Shaders/FluidSurface.compute's Composite kernel over the camera colour. The texture holds
// linear rgb already multiplied by its coverage a (0 outside the fluid, 1 inside), so the blend is premultiplied alpha:
// result = fluid.rgb + (1 - a) * camera. Drawn by Blitter.BlitTexture as one full-screen triangle (Core RP's Blit.hlsl
// Vert, source in _BlitTexture): one fluid texel per target pixel, or a half-resolution composite upsampled bilinearly
// (premultiplied colour interpolates correctly, softening the edge by a pixel).
Shader "Hidden/SoftBodyDynamics/FluidOverlay"
{
    SubShader
    {
        Tags { "RenderType" = "Transparent" "RenderPipeline" = "UniversalPipeline" }
        ZWrite Off
        ZTest Always
        Cull Off
        Blend One OneMinusSrcAlpha

        Pass
        {
            Name "FluidOverlay"

            HLSLPROGRAM
            #pragma vertex Vert
            #pragma fragment Frag

            // URP's Core.hlsl first, for the platform and XR macros Blit.hlsl relies on.
            #include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
            #include "Packages/com.unity.render-pipelines.core/Runtime/Utilities/Blit.hlsl"

            half4 Frag(Varyings input) : SV_Target
            {
                UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input);
                // Bilinear: at full resolution every pixel centre is a texel centre (the same as point sampling); at half
                // resolution it upsamples.
                return SAMPLE_TEXTURE2D_X_LOD(_BlitTexture, sampler_LinearClamp, input.texcoord, 0);
            }
            ENDHLSL
        }
    }
}
