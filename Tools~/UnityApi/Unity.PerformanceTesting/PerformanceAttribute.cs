using System;
using NUnit.Framework;

namespace Unity.PerformanceTesting
{
    // https://docs.unity3d.com/Packages/com.unity.test-framework.performance@3.2/api/Unity.PerformanceTesting.PerformanceAttribute.html
    // source: Runtime/Attributes/PerformanceAttribute.cs (3.1.0, 3.5.0). The real class also implements
    // UnityEngine.TestTools.IOuterUnityTestAction and NUnit's IApplyToTest; not declared here (the package does
    // not call them), so this stub needs no UnityEngine.TestRunner declarations.
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = false)]
    public class PerformanceAttribute : CategoryAttribute
    {
        // ...PerformanceAttribute.html#Unity_PerformanceTesting_PerformanceAttribute__ctor
        public PerformanceAttribute() : base("Performance") { }
    }
}
