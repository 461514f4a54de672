// a <= b for IEEE 754 binary32 operands, as the model's comparators decide
// it: NaN on either side is false, -0 equals +0, denormals compare as they
// are and infinities are ordinary extremes. Combinational.
module float_le (
    input  wire [31:0] a,
    input  wire [31:0] b,
    output wire        le
);
    wire a_nan = (&a[30:23]) & (|a[22:0]);
    wire b_nan = (&b[30:23]) & (|b[22:0]);
    wire both_zero = ~(|a[30:0]) & ~(|b[30:0]);
    // Sign-magnitude order: one magnitude comparator serves both signs.
    wire mag_le = a[30:0] <= b[30:0];
    wire mag_ge = a[30:0] >= b[30:0];
    reg ordered;
    always @* begin
        case ({a[31], b[31]})
            2'b00: ordered = mag_le;
            2'b10: ordered = 1'b1;
            2'b01: ordered = both_zero;
            default: ordered = mag_ge;
        endcase
    end
    assign le = ~a_nan & ~b_nan & (ordered | both_zero);
endmodule
