namespace Unity.PerformanceTesting
{
    // https://docs.unity3d.com/Packages/com.unity.test-framework.performance@3.2/api/Unity.PerformanceTesting.SampleGroup.html
    // source: Runtime/SampleGroup.cs (3.1.0, 3.5.0; the real class is [Serializable] and implements IDeserializationCallback)
    public class SampleGroup
    {
        // ...SampleGroup.html#Unity_PerformanceTesting_SampleGroup_Name
        public string Name;

        // ...SampleGroup.html#Unity_PerformanceTesting_SampleGroup__ctor_System_String_Unity_PerformanceTesting_SampleUnit_System_Boolean_
        public SampleGroup(string name, SampleUnit unit = SampleUnit.Millisecond, bool increaseIsBetter = false) => throw null;
    }
}
