using System;

namespace UnityEngine.TestTools
{
    // https://docs.unity3d.com/Packages/com.unity.test-framework@1.4/api/UnityEngine.TestTools.UnityTestAttribute.html
    // source: UnityEngine.TestRunner/NUnitExtensions/Attributes/UnityTestAttribute.cs (1.4.6):
    // [AttributeUsage(AttributeTargets.Method)] public class UnityTestAttribute : CombiningStrategyAttribute, IImplyFixture,
    // ISimpleTestBuilder, ITestBuilder, IApplyToTest. The NUnit base and interfaces are left out (the package only marks
    // methods with it), so this stub needs no NUnit reference.
    [AttributeUsage(AttributeTargets.Method)]
    public class UnityTestAttribute : Attribute
    {
        // https://docs.unity3d.com/Packages/com.unity.test-framework@1.4/api/UnityEngine.TestTools.UnityTestAttribute.-ctor.html
        public UnityTestAttribute() { }
    }
}
