namespace RobotControl.CoppeliaSim;

/// <summary>A call to CoppeliaSim failed: the base of the client's errors.</summary>
public class CoppeliaSimException : Exception
{
    /// <summary>Creates the exception.</summary>
    public CoppeliaSimException()
    {
    }

    /// <summary>Creates the exception with a message.</summary>
    public CoppeliaSimException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and its cause.</summary>
    public CoppeliaSimException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}

/// <summary>The server answered the call with an error; <see cref="Exception.Message"/> carries the server's message.</summary>
public sealed class CoppeliaSimServerException : CoppeliaSimException
{
    /// <summary>Creates the exception.</summary>
    public CoppeliaSimServerException()
    {
    }

    /// <summary>Creates the exception with a message.</summary>
    public CoppeliaSimServerException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and its cause.</summary>
    public CoppeliaSimServerException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}

/// <summary>No reply within the call's timeout, or the server ended the session: the connection is gone.</summary>
public sealed class CoppeliaSimConnectionException : CoppeliaSimException
{
    /// <summary>Creates the exception.</summary>
    public CoppeliaSimConnectionException()
    {
    }

    /// <summary>Creates the exception with a message.</summary>
    public CoppeliaSimConnectionException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and its cause.</summary>
    public CoppeliaSimConnectionException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}
