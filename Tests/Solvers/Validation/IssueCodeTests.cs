using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Every domain's issue codes reach <see cref="IssueCode"/> with their domain, number and name, and no number is used twice.</summary>
    public class IssueCodeTests
    {
        /// <summary>Every enum of the solver assembly named *IssueCode: one per <see cref="IssueDomain"/>.</summary>
        static Type[] DomainEnums() => typeof(IssueCode).Assembly.GetTypes()
            .Where(t => t.IsEnum && t.Name.EndsWith("IssueCode", StringComparison.Ordinal)).OrderBy(t => t.Name).ToArray();

        static IssueCode Convert(Type domainEnum, object member)
        {
            MethodInfo op = typeof(IssueCode).GetMethods(BindingFlags.Public | BindingFlags.Static)
                .Single(m => m.Name == "op_Implicit" && m.GetParameters()[0].ParameterType == domainEnum);
            return (IssueCode)op.Invoke(null, new[] { member });
        }

        [Test]
        public void EachDomain_HasOneEnumNamedAfterIt()
        {
            string[] enums = DomainEnums().Select(t => t.Name).ToArray();
            string[] domains = Enum.GetNames(typeof(IssueDomain)).Select(d => d + "IssueCode").OrderBy(n => n).ToArray();
            Assert.That(enums, Is.EqualTo(domains));
        }

        [Test]
        public void Numbers_AreUniqueAcrossDomains()
        {
            var owner = new Dictionary<int, string>();
            foreach (Type e in DomainEnums())
                foreach (object member in Enum.GetValues(e))
                {
                    int value = (int)member;
                    Assert.That(owner.ContainsKey(value), Is.False, $"{e.Name}.{member} = {value} is also {(owner.TryGetValue(value, out string o) ? o : "")}");
                    owner[value] = $"{e.Name}.{member}";
                }
        }

        [Test]
        public void Conversion_KeepsDomainNumberAndName()
        {
            foreach (Type e in DomainEnums())
                foreach (object member in Enum.GetValues(e))
                {
                    IssueCode code = Convert(e, member);
                    Assert.That(code.Domain + "IssueCode", Is.EqualTo(e.Name));
                    Assert.That(code.Value, Is.EqualTo((int)member));
                    Assert.That(code.Name, Is.EqualTo(member.ToString()));
                    Assert.That(code.ToString(), Is.EqualTo($"{e.Name}.{member}"));
                }
        }

        [Test]
        public void Codes_AreEqualOnlyToTheSameDomainAndNumber()
        {
            IssueCode sliver = FemIssueCode.TetrahedronSliver;
            Assert.That(sliver == FemIssueCode.TetrahedronSliver, Is.True);
            Assert.That(sliver != FemIssueCode.TetrahedronInverted, Is.True);
            Assert.That(sliver == TetrahedralMeshIssueCode.TetrahedronSliver, Is.False, "the same name in another domain is another code");
            Assert.That(sliver.Equals((object)(IssueCode)FemIssueCode.TetrahedronSliver), Is.True);
            Assert.That(sliver.GetHashCode(), Is.EqualTo(((IssueCode)FemIssueCode.TetrahedronSliver).GetHashCode()));
        }
    }
}
