namespace Unity.PerformanceTesting
{
    // https://docs.unity3d.com/Packages/com.unity.test-framework.performance@3.2/api/Unity.PerformanceTesting.SampleUnit.html
    // source: Runtime/Data/SampleUnit.cs (3.1.0, 3.5.0): all members, in declaration order (values are implicit).
    public enum SampleUnit
    {
        Nanosecond,
        Microsecond,
        Millisecond,
        Second,
        Byte,
        Kilobyte,
        Megabyte,
        Gigabyte,
        Undefined
    }
}
