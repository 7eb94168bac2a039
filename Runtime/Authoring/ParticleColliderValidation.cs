using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Every check on an authored collider, in one place: the baker refuses to bake a collider with an error,
    /// and the inspector shows the same list.
    /// </summary>
    public static class ParticleColliderValidation
    {
        /// <summary>Relative difference between scale factors above which a scale counts as non-uniform.</summary>
        public const float UniformScaleTolerance = 1e-3f;

        /// <summary>The issues of <paramref name="authoring"/> with its current transform.</summary>
        public static List<ValidationIssue> Validate(ParticleColliderAuthoring authoring)
        {
            var issues = new List<ValidationIssue>();
            var transform = authoring.transform;
            Validate(authoring.Definition, UnityMathConversions.ToFloat3(transform.position),
                UnityMathConversions.ToQuaternion(transform.rotation), UnityMathConversions.ToFloat3(transform.lossyScale),
                issues);
            return issues;
        }

        /// <summary>Appends the issues of <paramref name="collider"/> placed by the given transform to <paramref name="issues"/>.</summary>
        public static void Validate(in ParticleColliderDefinition collider, float3 position, quaternion rotation,
            float3 lossyScale, List<ValidationIssue> issues)
        {
            if (collider.Shape != ColliderShapeType.Plane && collider.Shape != ColliderShapeType.Sphere
                && collider.Shape != ColliderShapeType.Box && collider.Shape != ColliderShapeType.Capsule)
            {
                issues.Add(Error(ColliderIssueCode.ShapeInvalid,
                    $"Shape {(int)collider.Shape} is not Plane, Sphere, Box or Capsule. Pick one of them."));
                return;
            }

            if (!math.all(math.isfinite(position)) || !math.all(math.isfinite(rotation.value)) || !math.all(math.isfinite(lossyScale)))
                issues.Add(Error(ColliderIssueCode.TransformNotFinite,
                    "The transform's position, rotation or scale is NaN or infinite. Reset the Transform."));

            if (!math.all(math.isfinite(collider.Center)))
                issues.Add(Error(ColliderIssueCode.SizeNotFinite, "Center is NaN or infinite. Enter a finite point (m)."));

            float3 scale = math.abs(lossyScale);
            bool finiteScale = math.all(math.isfinite(scale));
            switch (collider.Shape)
            {
                case ColliderShapeType.Sphere:
                    CheckRadius(collider.Radius, issues);
                    CheckScale(scale, math.cmax(scale) == 0f, "sphere", issues);
                    if (finiteScale && (!IsUniform(scale.x, scale.y) || !IsUniform(scale.y, scale.z)))
                        issues.Add(Warning(ColliderIssueCode.NonUniformScale,
                            $"The sphere is scaled non-uniformly ({Format(lossyScale)}); its radius uses the largest factor, {math.cmax(scale):0.###}. "
                            + "Use a uniform scale, or a box or capsule for an elongated shape."));
                    break;
                case ColliderShapeType.Box:
                    if (!math.all(math.isfinite(collider.Size)))
                        issues.Add(Error(ColliderIssueCode.SizeNotFinite, "Size is NaN or infinite. Enter the box's full size along X, Y and Z (m)."));
                    else if (math.cmin(collider.Size) <= 0f)
                        issues.Add(Error(ColliderIssueCode.SizeNotPositive,
                            $"Size {Format(collider.Size)} has a zero or negative component. Every edge of the box must be longer than 0 m."));
                    CheckScale(scale, math.cmin(scale) == 0f, "box", issues);
                    break;
                case ColliderShapeType.Capsule:
                {
                    CheckRadius(collider.Radius, issues);
                    if (!math.isfinite(collider.Height))
                        issues.Add(Error(ColliderIssueCode.SizeNotFinite, "Height is NaN or infinite. Enter the capsule's tip-to-tip height (m)."));
                    else if (collider.Height < 0f)
                        issues.Add(Error(ColliderIssueCode.SizeNotPositive, $"Height {collider.Height} m is negative. Enter the capsule's tip-to-tip height (m)."));
                    else if (collider.Height < 2f * collider.Radius)
                        issues.Add(Warning(ColliderIssueCode.CapsuleShorterThanDiameter,
                            $"Height {collider.Height} m is less than the diameter {2f * collider.Radius} m, so the capsule is a sphere. "
                            + "Use the Sphere shape, or make the height at least twice the radius."));
                    if (collider.Direction > ColliderCapsuleAxis.Z)
                    {
                        issues.Add(Error(ColliderIssueCode.ShapeInvalid,
                            $"Capsule direction {(int)collider.Direction} is not X, Y or Z. Pick one of them."));
                        break;
                    }
                    float2 radial = ParticleColliderWorldShape.RadialScales(scale, collider.Direction);
                    float radialScale = ParticleColliderWorldShape.RadialScale(scale, collider.Direction);
                    CheckScale(scale, radialScale == 0f, "capsule", issues);
                    if (finiteScale && !IsUniform(radial.x, radial.y))
                        issues.Add(Warning(ColliderIssueCode.NonUniformScale,
                            $"The capsule is scaled differently across its {collider.Direction} axis ({Format(lossyScale)}); its radius uses the larger factor, {radialScale:0.###}. "
                            + "Scale it uniformly across its axis (stretching along the axis is fine)."));
                    break;
                }
            }
        }

        static void CheckRadius(float radius, List<ValidationIssue> issues)
        {
            if (!math.isfinite(radius))
                issues.Add(Error(ColliderIssueCode.SizeNotFinite, "Radius is NaN or infinite. Enter a radius in metres."));
            else if (radius <= 0f)
                issues.Add(Error(ColliderIssueCode.SizeNotPositive, $"Radius {radius} m is not positive. Enter a radius greater than 0 m."));
        }

        static void CheckScale(float3 absoluteScale, bool flattened, string shapeName, List<ValidationIssue> issues)
        {
            if (!math.all(math.isfinite(absoluteScale)))
                return; // reported as TransformNotFinite
            if (flattened)
                issues.Add(Error(ColliderIssueCode.ScaleZero,
                    $"The transform's scale {Format(absoluteScale)} has a zero factor, so the {shapeName} has no volume. Give every axis a non-zero scale."));
        }

        static bool IsUniform(float a, float b) => math.abs(a - b) <= UniformScaleTolerance * math.max(a, b);

        static string Format(float3 v) => $"({v.x:0.###}, {v.y:0.###}, {v.z:0.###})";

        static ValidationIssue Error(IssueCode code, string message) =>
            ValidationIssue.Error(code, -1, message);

        static ValidationIssue Warning(IssueCode code, string message) =>
            ValidationIssue.Warning(code, -1, message);
    }
}
