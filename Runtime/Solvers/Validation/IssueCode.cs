using System;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// What a <see cref="ValidationIssue"/> is about: one code of one domain. Each domain's codes are an enum beside its
    /// validator (<see cref="FemIssueCode"/> beside <see cref="FemParameterValidation"/>, …) and convert to this
    /// implicitly, so <c>issue.Code == FemIssueCode.TetrahedronSliver</c> reads as written. The numbers are unique
    /// across domains and stable: <see cref="Value"/> alone identifies a code.
    /// </summary>
    public readonly struct IssueCode : IEquatable<IssueCode>
    {
        /// <summary>The validator's domain: which enum <see cref="Value"/> belongs to.</summary>
        public readonly IssueDomain Domain;
        /// <summary>The code's number in its domain's enum.</summary>
        public readonly int Value;

        IssueCode(IssueDomain domain, int value)
        {
            Domain = domain;
            Value = value;
        }

        public static implicit operator IssueCode(MeshBuildIssueCode code) => new IssueCode(IssueDomain.MeshBuild, (int)code);
        public static implicit operator IssueCode(ParticleBodyIssueCode code) => new IssueCode(IssueDomain.ParticleBody, (int)code);
        public static implicit operator IssueCode(ShapeMatchingIssueCode code) => new IssueCode(IssueDomain.ShapeMatching, (int)code);
        public static implicit operator IssueCode(MassSpringIssueCode code) => new IssueCode(IssueDomain.MassSpring, (int)code);
        public static implicit operator IssueCode(FemIssueCode code) => new IssueCode(IssueDomain.Fem, (int)code);
        public static implicit operator IssueCode(TetrahedralMeshIssueCode code) => new IssueCode(IssueDomain.TetrahedralMesh, (int)code);
        public static implicit operator IssueCode(SoftBodyAuthoringIssueCode code) => new IssueCode(IssueDomain.SoftBodyAuthoring, (int)code);
        public static implicit operator IssueCode(ColliderIssueCode code) => new IssueCode(IssueDomain.Collider, (int)code);
        public static implicit operator IssueCode(FluidIssueCode code) => new IssueCode(IssueDomain.Fluid, (int)code);
        public static implicit operator IssueCode(FluidEmissionIssueCode code) => new IssueCode(IssueDomain.FluidEmission, (int)code);
        public static implicit operator IssueCode(FluidSurfaceIssueCode code) => new IssueCode(IssueDomain.FluidSurface, (int)code);

        /// <summary>The member's name in its domain's enum, e.g. "TetrahedronSliver".</summary>
        public string Name => Domain switch
        {
            IssueDomain.MeshBuild => ((MeshBuildIssueCode)Value).ToString(),
            IssueDomain.ParticleBody => ((ParticleBodyIssueCode)Value).ToString(),
            IssueDomain.ShapeMatching => ((ShapeMatchingIssueCode)Value).ToString(),
            IssueDomain.MassSpring => ((MassSpringIssueCode)Value).ToString(),
            IssueDomain.Fem => ((FemIssueCode)Value).ToString(),
            IssueDomain.TetrahedralMesh => ((TetrahedralMeshIssueCode)Value).ToString(),
            IssueDomain.SoftBodyAuthoring => ((SoftBodyAuthoringIssueCode)Value).ToString(),
            IssueDomain.Collider => ((ColliderIssueCode)Value).ToString(),
            IssueDomain.Fluid => ((FluidIssueCode)Value).ToString(),
            IssueDomain.FluidEmission => ((FluidEmissionIssueCode)Value).ToString(),
            IssueDomain.FluidSurface => ((FluidSurfaceIssueCode)Value).ToString(),
            _ => Value.ToString(),
        };

        public bool Equals(IssueCode other) => Domain == other.Domain && Value == other.Value;
        public override bool Equals(object obj) => obj is IssueCode other && Equals(other);
        public override int GetHashCode() => Value;
        public static bool operator ==(IssueCode a, IssueCode b) => a.Equals(b);
        public static bool operator !=(IssueCode a, IssueCode b) => !a.Equals(b);

        /// <summary>The enum and member, e.g. "FemIssueCode.TetrahedronSliver".</summary>
        public override string ToString() => Domain + "IssueCode." + Name;
    }
}
